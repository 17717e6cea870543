#pragma once
// File > Open recording: the topic chooser. Lists the recording's topics (type, count, rate,
// what TunnelMap can use each for, as `tunnelmap-cli topics` does), lets the user pick the
// depth, colour, camera-info and pose topics, the world frame and the time window, and shows
// the equivalent command line. Each choice starts at what the CLI would choose by itself.
#include <QDialog>
#include <map>
#include <string>

#include "core/recordings/recording.h"
#include "core/recordings/recording_options.h"
#include "core/recordings/topic_roles.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace tunnelmap::ui {

class RecordingDialog : public QDialog {
  Q_OBJECT
 public:
  RecordingDialog(const QString& path, const recordings::Recording& rec,
                  const std::map<std::string, recordings::TopicRole>& roles, QWidget* parent = nullptr);

  recordings::RecordingOptions options() const;
  // What `tunnelmap-cli detect` would be given for the same choice, or why there is none.
  QString command_line() const { return command_; }
  bool acceptable() const;  // the choice names a depth topic and every role resolves
  // The combo boxes by role ("depth", "color", "camera_info", "pose"), for tests.
  QComboBox* topic_box(const QString& role) const;
  int depth_frames() const;  // messages on the chosen depth topic, before --every

 private:
  void add_topic_table();
  void add_choices();
  QComboBox* add_topic_box(const QString& role, recordings::TopicRole r, bool optional);
  QComboBox* add_imu_box();
  void refresh();

  QString path_;
  const recordings::Recording& rec_;
  std::map<std::string, recordings::TopicRole> roles_;
  std::map<QString, QComboBox*> boxes_;
  QLineEdit* world_frame_ = nullptr;
  QDoubleSpinBox *start_ = nullptr, *duration_ = nullptr;
  QSpinBox* every_ = nullptr;
  QLabel* command_label_ = nullptr;
  QPushButton* ok_ = nullptr;
  QString command_;
  bool acceptable_ = false;
};

}  // namespace tunnelmap::ui
