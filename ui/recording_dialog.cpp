#include "ui/recording_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include "core/util/error.h"

namespace tunnelmap::ui {

using namespace recordings;

namespace {

QString rate_text(const TopicInfo& t) {
  const auto r = t.rate_hz();
  return r ? QString::number(*r, 'f', 2) : QStringLiteral("–");
}

std::vector<std::string> topics_with(const std::map<std::string, TopicRole>& roles, TopicRole r) {
  std::vector<std::string> out;
  for (const auto& [name, role] : roles)
    if (role == r) out.push_back(name);
  return out;
}

std::string chosen(const QComboBox* box) { return box ? box->currentData().toString().toStdString() : ""; }

// A spin box whose lowest value reads as "not set" (the CLI flag left out).
QDoubleSpinBox* seconds_box(const QString& unset_text) {
  auto* box = new QDoubleSpinBox;
  box->setRange(-1.0, 1e6);
  box->setDecimals(2);
  box->setSuffix(" s");
  box->setSpecialValueText(unset_text);
  box->setValue(-1.0);
  return box;
}

std::optional<double> seconds_of(const QDoubleSpinBox* box) {
  return box->value() < 0.0 ? std::nullopt : std::optional<double>(box->value());
}

}  // namespace

RecordingDialog::RecordingDialog(const QString& path, const Recording& rec,
                                 const std::map<std::string, TopicRole>& roles, QWidget* parent)
    : QDialog(parent), path_(path), rec_(rec), roles_(roles) {
  setObjectName("recordingDialog");
  setWindowTitle(tr("Open recording — %1").arg(QFileInfo(path).fileName()));
  auto* layout = new QVBoxLayout(this);
  const RecordingSummary& s = rec.summary();
  auto* heading = new QLabel(tr("%1: %2, %3 file(s), %4 topics, %5 messages")
                                 .arg(path, QString::fromStdString(s.format))
                                 .arg(s.files.size())
                                 .arg(s.topics.size())
                                 .arg(s.message_count()));
  heading->setWordWrap(true);
  layout->addWidget(heading);
  if (s.truncation_note) layout->addWidget(new QLabel(tr("Truncated: %1").arg(QString::fromStdString(*s.truncation_note))));
  add_topic_table();
  add_choices();
  refresh();
  resize(760, 560);
}

void RecordingDialog::add_topic_table() {
  const RecordingSummary& s = rec_.summary();
  auto* table = new QTableWidget(static_cast<int>(s.topics.size()), 5, this);
  table->setObjectName("recordingTopics");
  table->setHorizontalHeaderLabels({tr("Topic"), tr("Type"), tr("Count"), tr("Rate (Hz)"), tr("Use")});
  table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table->verticalHeader()->hide();
  for (int row = 0; row < static_cast<int>(s.topics.size()); ++row) {
    const TopicInfo& t = s.topics[static_cast<std::size_t>(row)];
    table->setItem(row, 0, new QTableWidgetItem(QString::fromStdString(t.name)));
    table->setItem(row, 1, new QTableWidgetItem(QString::fromStdString(t.type)));
    table->setItem(row, 2, new QTableWidgetItem(QString::number(t.message_count)));
    table->setItem(row, 3, new QTableWidgetItem(rate_text(t)));
    table->setItem(row, 4, new QTableWidgetItem(QString::fromUtf8(topic_role_name(roles_.at(t.name)))));
  }
  table->resizeColumnsToContents();
  table->horizontalHeader()->setStretchLastSection(true);
  static_cast<QVBoxLayout*>(layout())->addWidget(table, 1);
}

QComboBox* RecordingDialog::add_topic_box(const QString& role, TopicRole r, bool optional) {
  auto* box = new QComboBox(this);
  box->setObjectName(role + "Topic");
  for (const std::string& t : topics_with(roles_, r)) box->addItem(QString::fromStdString(t), QString::fromStdString(t));
  if (box->count() == 0) box->addItem(optional ? tr("(none in this recording)") : tr("(no candidate)"), QString());
  boxes_[role] = box;
  connect(box, qOverload<int>(&QComboBox::currentIndexChanged), this, &RecordingDialog::refresh);
  return box;
}

// The IMU topic, or none; with several candidates none is read until the user picks one, as on
// the command line.
QComboBox* RecordingDialog::add_imu_box() {
  QComboBox* imu = add_topic_box("imu", TopicRole::Imu, true);
  if (imu->itemData(0).toString().isEmpty()) imu->removeItem(0);
  imu->addItem(tr("none: no gravity"), QStringLiteral("none"));
  if (imu->count() != 2) imu->setCurrentIndex(imu->count() - 1);
  return imu;
}

void RecordingDialog::add_choices() {
  auto* form = new QFormLayout;
  form->addRow(tr("Depth topic"), add_topic_box("depth", TopicRole::Depth, false));
  form->addRow(tr("Colour topic"), add_topic_box("color", TopicRole::Color, true));
  form->addRow(tr("Camera info topic"), add_topic_box("camera_info", TopicRole::CameraInfo, true));
  QComboBox* pose = add_topic_box("pose", TopicRole::Pose, true);
  if (!topics_with(roles_, TopicRole::Tf).empty()) {
    if (pose->itemData(0).toString().isEmpty()) pose->removeItem(0);
    pose->insertItem(0, tr("TF tree (/tf and /tf_static)"), QString());
    pose->setCurrentIndex(0);
  }
  form->addRow(tr("Poses"), pose);
  form->addRow(tr("IMU (gravity)"), add_imu_box());
  try {  // start where the CLI would: the camera info beside the depth topic
    const TopicChoice auto_choice = choose_topics(rec_, roles_, options());
    QComboBox* info = boxes_["camera_info"];
    const int i = info->findData(QString::fromStdString(auto_choice.camera_info));
    if (i >= 0) info->setCurrentIndex(i);
  } catch (const std::exception&) {
    // Several candidates: the first is shown, the user picks.
  }
  world_frame_ = new QLineEdit(this);
  world_frame_->setObjectName("worldFrame");
  world_frame_->setPlaceholderText(tr("automatic: map or odom when present"));
  connect(world_frame_, &QLineEdit::textChanged, this, &RecordingDialog::refresh);
  form->addRow(tr("World frame"), world_frame_);
  start_ = seconds_box(tr("from the first message"));
  duration_ = seconds_box(tr("to the end"));
  every_ = new QSpinBox(this);
  every_->setRange(1, 1000);
  every_->setObjectName("everyNth");
  for (QDoubleSpinBox* b : {start_, duration_}) connect(b, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &RecordingDialog::refresh);
  connect(every_, qOverload<int>(&QSpinBox::valueChanged), this, &RecordingDialog::refresh);
  form->addRow(tr("Start"), start_);
  form->addRow(tr("Duration"), duration_);
  form->addRow(tr("Keep one frame in"), every_);
  static_cast<QVBoxLayout*>(layout())->addLayout(form);
  command_label_ = new QLabel(this);
  command_label_->setObjectName("recordingCommand");
  command_label_->setWordWrap(true);
  command_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  static_cast<QVBoxLayout*>(layout())->addWidget(command_label_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel, this);
  ok_ = buttons->button(QDialogButtonBox::Open);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  static_cast<QVBoxLayout*>(layout())->addWidget(buttons);
}

RecordingOptions RecordingDialog::options() const {
  RecordingOptions o;
  o.depth_topic = chosen(boxes_.at("depth"));
  o.color_topic = chosen(boxes_.at("color"));
  o.camera_info_topic = chosen(boxes_.at("camera_info"));
  o.pose_topic = chosen(boxes_.at("pose"));
  o.imu_topic = chosen(boxes_.at("imu"));
  if (world_frame_) o.world_frame = world_frame_->text().trimmed().toStdString();
  if (start_) o.start_s = seconds_of(start_);
  if (duration_) o.duration_s = seconds_of(duration_);
  if (every_) o.every = every_->value();
  return o;
}

void RecordingDialog::refresh() {
  if (!command_label_) return;  // still being built
  try {
    const RecordingOptions o = options();
    command_ = QString::fromStdString(suggested_command(path_.toStdString(), choose_topics(rec_, roles_, o), o));
    acceptable_ = true;
  } catch (const std::exception& e) {
    command_ = QString::fromStdString(e.what());
    acceptable_ = false;
  }
  command_label_->setText(acceptable_ ? tr("Same as: %1").arg(command_) : tr("Cannot open: %1").arg(command_));
  ok_->setEnabled(acceptable_);
}

bool RecordingDialog::acceptable() const { return acceptable_; }

QComboBox* RecordingDialog::topic_box(const QString& role) const {
  const auto it = boxes_.find(role);
  return it == boxes_.end() ? nullptr : it->second;
}

int RecordingDialog::depth_frames() const {
  const TopicInfo* t = rec_.summary().topic(chosen(boxes_.at("depth")));
  return t ? static_cast<int>(t->message_count) : 0;
}

}  // namespace tunnelmap::ui
