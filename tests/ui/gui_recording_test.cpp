// File > Open recording in a real window (run under xvfb-run -a): a simulated posed sequence
// written as an MCAP with two depth topics is indexed, its topics chosen in the dialog (the
// choice and the command line it shows are checked), read with progress and opened with its
// poses; Cancel and a broken recording keep the input that was open and leave no temporary
// folder behind. TUNNELMAP_GUI_SHOT_DIR=DIR keeps a screenshot of the dialog.
#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QProgressBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest/QtTest>
#include <QSlider>
#include <filesystem>
#include <set>
#include <fstream>

#include "core/io/dataset.h"
#include "core/sim/sim_config.h"
#include "core/sim/sim_dataset_writer.h"
#include "tests/support/mcap_writer.h"
#include "tests/support/posed_bag.h"
#include "ui/main_window.h"
#include "ui/recording_dialog.h"
#include "ui/recording_opener.h"
#include "ui/timeline_widget.h"

using tunnelmap::ui::MainWindow;
using tunnelmap::ui::RecordingDialog;
using tunnelmap::ui::RecordingOpener;

namespace {

constexpr const char* kRearDepthTopic = "/rear/depth/image_raw";

// Temporary extraction folders of recordings (core/recordings/recording_dataset.cpp).
// The extraction folders in the temporary directory, by name.
std::set<std::string> extraction_folders() {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
    if (e.path().filename().string().rfind("tunnelmap-recording-", 0) == 0) names.insert(e.path().filename().string());
  return names;
}

// Folders present now that were not before: what this window left behind.
std::vector<std::string> new_folders(const std::set<std::string>& before) {
  std::vector<std::string> added;
  for (const std::string& name : extraction_folders())
    if (!before.count(name)) added.push_back(name);
  return added;
}

}  // namespace

class GuiRecordingTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir dir_;
  QString dataset_, bag_;
  tunnelmap::Dataset ds_;

  // Waits until the opener is idle again; false on timeout.
  static bool wait_idle(RecordingOpener& opener, int timeout_ms = 60000) {
    QElapsedTimer t;
    t.start();
    while (opener.busy() && t.elapsed() < timeout_ms) QTest::qWait(20);
    return !opener.busy();
  }

  static MainWindow* shown_window() {
    auto* w = new MainWindow;
    w->suppress_dialogs = true;
    w->resize(1280, 800);
    w->show();
    return w;
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    QVERIFY(dir_.isValid());
    // Extractions go to a temporary directory of this test's own: tests running beside it make
    // and remove extraction folders in the shared one.
    QVERIFY(QDir().mkpath(dir_.filePath("tmp")));
    qputenv("TMPDIR", dir_.filePath("tmp").toLocal8Bit());
    dataset_ = dir_.filePath("sim");
    tunnelmap::SimConfig config;
    config.frames = 6;
    config.frame_interval_s = 0.2;  // a robot scanning at its stops, with an IMU
    config.imu_gravity_deg = 0.2;
    tunnelmap::write_sim_dataset(dataset_.toStdString(), config);
    ds_ = tunnelmap::read_dataset(dataset_.toStdString());
    bag_ = dir_.filePath("two_cameras.mcap");
    tunnelmap::testing::McapWriter writer(bag_.toStdString(), {});
    tunnelmap::testing::write_posed_bag(ds_, [&](const std::string& topic, const std::string& type, std::int64_t t,
                                                 const std::vector<std::uint8_t>& cdr) {
      writer.write(topic, type, static_cast<std::uint64_t>(t), cdr);
      // A second depth camera: the automatic choice is then ambiguous and the user picks.
      if (topic == tunnelmap::testing::kBagDepthTopic) writer.write(kRearDepthTopic, type, static_cast<std::uint64_t>(t), cdr);
    }, true);
    writer.close();
  }

  void theDialogListsTheTopicsAndOpensTheChosenOnes() {
    std::unique_ptr<MainWindow> w(shown_window());
    QVERIFY(QTest::qWaitForWindowExposed(w.get()));
    QString command;
    int rows = 0;
    bool initially_acceptable = false;
    QString imu_shown, imu_off_command;
    w->recording_opener()->choose_topics = [&](RecordingDialog& d) {
      rows = d.findChild<QTableWidget*>("recordingTopics")->rowCount();
      QComboBox* depth = d.topic_box("depth");
      initially_acceptable = d.acceptable();
      imu_shown = d.topic_box("imu")->currentText();
      QComboBox* imu = d.topic_box("imu");
      imu->setCurrentIndex(imu->findData("none"));
      imu_off_command = d.command_line();
      imu->setCurrentIndex(0);
      depth->setCurrentIndex(depth->findData(tunnelmap::testing::kBagDepthTopic));
      d.findChild<QSpinBox*>()->setValue(2);  // every 2nd frame
      command = d.command_line();
      const QByteArray shots = qgetenv("TUNNELMAP_GUI_SHOT_DIR");
      if (!shots.isEmpty()) {
        d.show();
        QTest::qWait(200);
        d.grab().save(QDir(QString::fromLocal8Bit(shots)).filePath("recording-dialog.png"));
      }
      return d.acceptable();
    };
    QSignalSpy shown(w.get(), &MainWindow::frameShown);
    QVERIFY(w->open_interactively(bag_));
    QVERIFY(w->findChild<QProgressBar*>()->isVisible());  // indexing shows progress at once
    QVERIFY(wait_idle(*w->recording_opener()));
    QVERIFY2(w->last_error().isEmpty(), qPrintable(w->last_error()));
    // depth twice, colour, camera info, odometry, IMU
    QCOMPARE(rows, 6);
    QCOMPARE(imu_shown, QString(tunnelmap::testing::kBagImuTopic));  // the only one, chosen
    QVERIFY2(command.contains(QString("--imu-topic ") + tunnelmap::testing::kBagImuTopic), qPrintable(command));
    QVERIFY2(imu_off_command.contains("--imu-topic none"), qPrintable(imu_off_command));
    QVERIFY(initially_acceptable);  // the first depth topic is preselected
    QVERIFY2(command.contains(QString("--depth-topic ") + tunnelmap::testing::kBagDepthTopic), qPrintable(command));
    QVERIFY2(command.contains("--every 2"), qPrintable(command));
    QVERIFY2(command.contains("--pose-topic /odom"), qPrintable(command));
    QCOMPARE(w->input_path(), bag_);
    QVERIFY(shown.count() > 0 || shown.wait(20000));
    QVERIFY(!w->findChild<QProgressBar*>()->isVisible());
    // Frames 0, 2 and 4 of the six, each with its pose from the odometry.
    QCOMPARE(w->timeline()->slider()->maximum(), 2);
    expect_shown_pose(*w, 0);
    QVERIFY(w->select_frame(1));
    QVERIFY(shown.wait(20000));
    expect_shown_pose(*w, 2);
    QCOMPARE(w->current()->frame.width, 640);
  }

  void aDialogClosedOrCancelKeepsTheOpenInput() {
    std::unique_ptr<MainWindow> w(shown_window());
    QVERIFY(QTest::qWaitForWindowExposed(w.get()));
    QSignalSpy shown(w.get(), &MainWindow::frameShown);
    QVERIFY(w->open_input(dataset_));
    QVERIFY(shown.wait(20000));  // the dataset's run has set its status line
    const std::set<std::string> folders_before = extraction_folders();
    w->recording_opener()->choose_topics = [](RecordingDialog&) { return false; };
    QVERIFY(w->open_interactively(bag_));
    QVERIFY(wait_idle(*w->recording_opener()));
    QCOMPARE(w->input_path(), dataset_);
    QVERIFY2(w->status_text().startsWith("Not opened"), qPrintable(w->status_text()));

    // Cancel while the frames are read: the first progress report stops the extraction.
    w->recording_opener()->choose_topics = [&](RecordingDialog& d) {
      d.topic_box("depth")->setCurrentIndex(d.topic_box("depth")->findData(kRearDepthTopic));
      w->recording_opener()->cancel();
      return true;
    };
    QVERIFY(w->open_interactively(bag_));
    QVERIFY(wait_idle(*w->recording_opener()));
    QCOMPARE(w->input_path(), dataset_);
    QVERIFY2(w->status_text().startsWith("Cancelled"), qPrintable(w->status_text()));
    QVERIFY(w->last_error().isEmpty());
    QVERIFY(new_folders(folders_before).empty());  // nothing left behind
    QVERIFY(!w->findChild<QProgressBar*>()->isVisible());
  }

  void aBrokenRecordingIsOneErrorNamingTheFile() {
    std::unique_ptr<MainWindow> w(shown_window());
    QVERIFY(QTest::qWaitForWindowExposed(w.get()));
    QSignalSpy shown(w.get(), &MainWindow::frameShown);
    QVERIFY(w->open_input(dataset_));
    QVERIFY(shown.wait(20000));
    const QString broken = dir_.filePath("broken.mcap");
    std::ofstream(broken.toStdString()) << "\x89MCAP0\r\nnot a recording";
    bool asked = false;
    w->recording_opener()->choose_topics = [&](RecordingDialog&) { return asked = true; };
    QSignalSpy errors(w.get(), &MainWindow::errorShown);
    QVERIFY(w->open_interactively(broken));
    QVERIFY(wait_idle(*w->recording_opener()));
    QCOMPARE(errors.count(), 1);
    QVERIFY2(w->last_error().contains("broken.mcap"), qPrintable(w->last_error()));
    QVERIFY(!w->last_error().contains('\n'));
    QVERIFY(!asked);
    QCOMPARE(w->input_path(), dataset_);
  }

 private:
  void expect_shown_pose(const MainWindow& w, std::size_t dataset_frame) {
    QVERIFY(w.current());
    const auto& pose = w.current()->frame.pose;
    QVERIFY(pose.has_value());
    const double diff = (pose->matrix() - ds_.frames[dataset_frame].pose->matrix()).cwiseAbs().maxCoeff();
    QVERIFY2(diff < 1e-6, qPrintable(QString("frame %1: pose off by %2").arg(dataset_frame).arg(diff)));
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("TunnelMapTest");
  GuiRecordingTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "gui_recording_test.moc"
