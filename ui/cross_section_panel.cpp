#include "ui/cross_section_panel.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace tunnelmap::ui {

namespace {
constexpr int kSliderSteps = 1000;
constexpr std::size_t kMaxDrawnPoints = 20000;  // the cut is measured on all of the slab's points
}

CrossSectionPanel::CrossSectionPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* row = new QHBoxLayout;
  // Ahead of the shown frame's camera, not the map's station: the map's stations run from the
  // first frame's camera, and a station chosen on the profile shows a frame that sees it.
  row->addWidget(new QLabel(tr("Ahead")));
  slider_ = new QSlider(Qt::Horizontal);
  slider_->setRange(0, kSliderSteps);
  slider_->setMinimumWidth(60);
  slider_->setToolTip(tr("Distance ahead of the camera along the tunnel axis"));
  row->addWidget(slider_, 1);
  station_ = new QDoubleSpinBox;
  station_->setDecimals(2);
  station_->setSingleStep(0.05);
  station_->setSuffix(tr(" m"));
  station_->setRange(0.0, 20.0);
  station_->setValue(kDefaultAheadM);
  row->addWidget(station_);
  layout->addLayout(row);
  auto* slab_row = new QHBoxLayout;
  slab_row->addWidget(new QLabel(tr("Slab \u00b1")));
  thickness_ = new QDoubleSpinBox;
  thickness_->setDecimals(0);
  thickness_->setRange(5, 250);
  thickness_->setSingleStep(5);
  thickness_->setValue(25);
  thickness_->setSuffix(tr(" mm"));
  thickness_->setToolTip(tr("Points within this distance of the section plane are drawn"));
  slab_row->addWidget(thickness_);
  slab_row->addStretch(1);
  layout->addLayout(slab_row);
  range_label_ = new QLabel;
  range_label_->setWordWrap(true);
  layout->addWidget(range_label_);
  view_ = new CrossSectionView;
  layout->addWidget(view_, 1);

  connect(slider_, &QSlider::valueChanged, this, [this](int v) {
    set_station(range_.from_m + (range_.to_m - range_.from_m) * v / kSliderSteps);
  });
  connect(station_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
    wanted_m_ = v;
    recompute();
    emit stationChanged(station());
  });
  connect(thickness_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double) { recompute(); });
}

double CrossSectionPanel::station() const { return station_->value(); }

void CrossSectionPanel::set_station(double station_m) {
  if (std::abs(station_m - station_->value()) < 1e-9) return;
  station_->setValue(station_m);  // recomputes and emits through the spin box
}

void CrossSectionPanel::set_frame(std::shared_ptr<const scene::ProcessedFrame> frame,
                                  std::optional<double> design_width_m, std::optional<double> design_height_m,
                                  double zone_gap_m) {
  frame_ = std::move(frame);
  design_w_ = design_width_m;
  design_h_ = design_height_m;
  zone_gap_m_ = zone_gap_m;
  range_ = frame_ && frame_->result.map.detected ? visible_stations(frame_->result.map) : StationRange{};
  const bool usable = range_.to_m > range_.from_m;
  slider_->setEnabled(usable);
  // The distance last asked for, as near as this frame's walls allow: a frame whose walls end
  // short of it does not move the cut for the frames after it.
  if (usable) {
    const QSignalBlocker block(station_);
    station_->setValue(std::clamp(wanted_m_, range_.from_m, range_.to_m));
  }
  recompute();
}

// The stations the frame's walls reach, and whether the cut lies among them (a plate the map
// asks for may stand beyond the walls the frame measured).
void CrossSectionPanel::update_range_label() {
  if (range_.to_m <= range_.from_m) {
    range_label_->setText(tr("No tunnel in this frame: the section shows its points only"));
    return;
  }
  const QString range = tr("The frame's walls run from %1 to %2 m ahead").arg(range_.from_m, 0, 'f', 2).arg(range_.to_m, 0, 'f', 2);
  const double s = station();
  range_label_->setText(s >= range_.from_m && s <= range_.to_m
                            ? range
                            : range + tr("; the cut at %1 m lies outside them").arg(s, 0, 'f', 2));
}

void CrossSectionPanel::recompute() {
  update_range_label();
  if (range_.to_m > range_.from_m) {
    const QSignalBlocker block(slider_);
    slider_->setValue(static_cast<int>(std::lround((station() - range_.from_m) / (range_.to_m - range_.from_m) * kSliderSteps)));
  }
  if (!frame_) return view_->clear();
  const FrameResult& r = frame_->result;
  view_->set_section(cross_section(r.cloud, r.planes, r.map, station(), thickness_->value() / 1000.0, design_w_,
                                   design_h_, kMaxDrawnPoints, zone_gap_m_));
}

}  // namespace tunnelmap::ui
