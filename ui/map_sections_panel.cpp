#include "ui/map_sections_panel.h"

#include <QHeaderView>
#include <QLabel>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <cmath>
#include <optional>

#include "core/mapping/rescan_stretches.h"

namespace tunnelmap::ui {

namespace {

constexpr int kStationRole = Qt::UserRole;  // the station a row stands for, in metres
constexpr int kFromRole = Qt::UserRole + 1, kToRole = Qt::UserRole + 2;  // a section's extent

enum Column { kWhere, kWidth, kHeight, kDeviation, kFrames, kColumns };

QString metres(double v) { return QString::number(v, 'f', 3); }

// A station's dimension: measured and context values as numbers, a design fill labelled so (in
// italics: it was not measured), an unseen one as "–".
QString dimension(double value, DimensionSource source) {
  if (source == DimensionSource::Unseen) return QStringLiteral("–");
  if (source == DimensionSource::Design) return QObject::tr("design");
  return metres(value);
}

QString deviation_text(const Station& s) {
  auto mm = [](const std::optional<double>& d) { return d ? QString::number(*d, 'f', 1) : QStringLiteral("–"); };
  return QObject::tr("w %1, h %2").arg(mm(s.width_dev_mm), mm(s.height_dev_mm));
}

QTreeWidgetItem* group(QTreeWidget* tree, const QString& title) {
  auto* item = new QTreeWidgetItem(tree, {title});
  item->setFirstColumnSpanned(true);
  item->setFlags(Qt::ItemIsEnabled);
  item->setExpanded(true);
  return item;
}

QTreeWidgetItem* row(QTreeWidgetItem* parent, double station_m, const QStringList& cells) {
  auto* item = new QTreeWidgetItem(parent, cells);
  item->setData(kWhere, kStationRole, station_m);
  for (int c = kWidth; c < kColumns; ++c) item->setTextAlignment(c, Qt::AlignRight | Qt::AlignVCenter);
  return item;
}

}  // namespace

MapSectionsPanel::MapSectionsPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  tree_ = new QTreeWidget(this);
  tree_->setColumnCount(kColumns);
  tree_->setHeaderLabels({tr("Station (m)"), tr("Width (m)"), tr("Height (m)"), tr("Off design (mm) / detail"), tr("Frames")});
  tree_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
  tree_->header()->setStretchLastSection(false);  // the frame counts stay under their header
  tree_->setRootIsDecorated(true);
  layout->addWidget(summary_);
  layout->addWidget(tree_, 1);
  connect(tree_, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* item) {
    const QVariant at = item->data(kWhere, kStationRole);
    if (at.isValid()) emit stationChosen(at.toDouble());
  });
  clear();
}

void MapSectionsPanel::clear() {
  tree_->clear();
  notes_ = sections_ = out_of_tolerance_ = rescan_ = diaphragms_ = compartments_ = nullptr;
  summary_->setText(tr("No map: Processing ▸ Map tunnel on a posed dataset lists its sections here."));
}

void MapSectionsPanel::set_map(const StationMap& map, const std::vector<std::string>& notes) {
  clear();
  if (!map.ok) return;
  add_notes(notes);
  add_sections(map);
  add_out_of_tolerance(map);
  add_rescan(map);
  add_diaphragms(map);
  add_compartments(map);
  const bool design = map.options.design_width_m || map.options.design_height_m;
  summary_->setText(design ? tr("%1 section(s), %2 of %3 stations out of tolerance (±%4 mm of the design)")
                                 .arg(map.sections.size())
                                 .arg(map.out_of_tolerance().size())
                                 .arg(map.stations.size())
                                 .arg(map.options.tolerance_mm)
                           : tr("%1 section(s) over %2 stations; no design, so no tolerance check")
                                 .arg(map.sections.size())
                                 .arg(map.stations.size()));
}

// A note is a sentence, not a row of numbers: it spans the columns, whole in its tooltip.
void MapSectionsPanel::add_notes(const std::vector<std::string>& notes) {
  if (notes.empty()) return;
  notes_ = group(tree_, tr("Notes (%1)").arg(notes.size()));
  for (const std::string& note : notes) {
    const QString text = QString::fromStdString(note);
    auto* item = new QTreeWidgetItem(notes_, {text});
    item->setFirstColumnSpanned(true);
    item->setToolTip(kWhere, text);
    item->setForeground(kWhere, Qt::darkRed);
  }
}

void MapSectionsPanel::add_sections(const StationMap& map) {
  sections_ = group(tree_, tr("Sections (%1)").arg(map.sections.size()));
  for (const Section& s : map.sections) {
    QTreeWidgetItem* item =
        row(sections_, 0.5 * (s.from_m + s.to_m),
            {tr("%1 – %2").arg(s.from_m, 0, 'f', 2).arg(s.to_m, 0, 'f', 2), metres(s.width_m), metres(s.height_m),
             QString(), QString::number(s.frames)});
    item->setData(kWhere, kFromRole, s.from_m);
    item->setData(kWhere, kToRole, s.to_m);
  }
}

void MapSectionsPanel::add_out_of_tolerance(const StationMap& map) {
  if (!map.options.design_width_m && !map.options.design_height_m) {
    out_of_tolerance_ = group(tree_, tr("Out of tolerance: not checked, no design cross-section given"));
    return;
  }
  const auto stations = map.out_of_tolerance();
  out_of_tolerance_ = group(tree_, tr("Out of tolerance (%1)").arg(stations.size()));
  for (const Station* s : stations) {
    QTreeWidgetItem* item =
        row(out_of_tolerance_, s->station_m,
            {QString::number(s->station_m, 'f', 2), dimension(s->width_m, s->width_source),
             dimension(s->height_m, s->height_source), deviation_text(*s), QString::number(s->frames)});
    for (int c : {kWidth, kHeight}) {
      const DimensionSource source = c == kWidth ? s->width_source : s->height_source;
      if (source != DimensionSource::Design) continue;
      QFont italic = item->font(c);
      italic.setItalic(true);
      item->setFont(c, italic);
      item->setForeground(c, Qt::gray);
    }
  }
}

// A stretch's row names the dimension no frame measured in its column; a joint inside it is
// flagged, and the row's tooltip says why it is listed. A click shows its middle.
void MapSectionsPanel::add_rescan(const StationMap& map) {
  const std::vector<RescanStretch> stretches = rescan_stretches(map);
  if (stretches.empty()) return;
  rescan_ = group(tree_, tr("To rescan (%1)").arg(stretches.size()));
  for (const RescanStretch& r : stretches) {
    const bool width = r.dimension == StationDimension::Width;
    QTreeWidgetItem* item =
        row(rescan_, 0.5 * (r.from_m + r.to_m),
            {tr("%1 – %2").arg(r.from_m, 0, 'f', 2).arg(r.to_m, 0, 'f', 2), width ? tr("not measured") : QString(),
             width ? QString() : tr("not measured"), r.joint_inside ? tr("joint inside") : QString(), QString()});
    for (int c = kWhere; c < kColumns; ++c) item->setToolTip(c, QString::fromStdString(r.reason));
    if (r.joint_inside) item->setForeground(kDeviation, Qt::darkRed);
  }
}

// A plate's row: its station, its manhole's width and height in those columns, and the
// opening's shape (or why there is none) beside them; the clearances and kind in its tooltip.
void MapSectionsPanel::add_diaphragms(const StationMap& map) {
  const auto& plates = map.girder.diaphragms;
  if (plates.empty()) return;
  diaphragms_ = group(tree_, tr("Diaphragms (%1): manhole width and height").arg(plates.size()));
  for (const Diaphragm& d : plates) {
    const std::optional<Manhole>& m = d.manhole;
    const QString what = m                     ? QString::fromStdString(m->shape == "rounded_rectangle" ? "rounded rectangle" : m->shape)
                         : d.kind == "end_wall" ? tr("end wall")
                         : d.closed             ? tr("closed: no opening")
                                                : tr("no manhole");
    QTreeWidgetItem* item = row(diaphragms_, d.station_m,
                                {QString::number(d.station_m, 'f', 3), m ? metres(m->width_m) : QStringLiteral("–"),
                                 m ? metres(m->height_m) : QStringLiteral("–"), what, QString::number(d.seen_by_frames)});
    item->setTextAlignment(kDeviation, Qt::AlignLeft | Qt::AlignVCenter);
    QString tip = d.kind == "end_wall" ? tr("End wall at station %1 m").arg(d.station_m, 0, 'f', 3)
                                       : tr("Plate across the girder at station %1 m").arg(d.station_m, 0, 'f', 3);
    if (m) {
      const auto clearance = [](double c) { return std::isfinite(c) ? metres(c) + QStringLiteral(" m") : QObject::tr("not measured"); };
      tip += tr("\nclearance to the left wall %1, right %2, roof %3, floor %4")
                 .arg(clearance(m->clearance_m[0]), clearance(m->clearance_m[1]), clearance(m->clearance_m[2]),
                      clearance(m->clearance_m[3]));
    } else if (!d.manhole_reason.empty()) {
      tip += QStringLiteral("\n") + QString::fromStdString(d.manhole_reason);
    }
    for (int c = kWhere; c < kColumns; ++c) item->setToolTip(c, tip);
  }
}

// The stretches between the plates, with the size measured inside each ("–": none measured).
void MapSectionsPanel::add_compartments(const StationMap& map) {
  const auto& parts = map.girder.compartments;
  if (parts.empty()) return;
  compartments_ = group(tree_, tr("Compartments (%1)").arg(parts.size()));
  const auto size = [](double v) { return std::isfinite(v) ? metres(v) : QStringLiteral("–"); };
  for (const Compartment& c : parts) {
    QTreeWidgetItem* item =
        row(compartments_, 0.5 * (c.from_m + c.to_m),
            {tr("%1 – %2").arg(c.from_m, 0, 'f', 2).arg(c.to_m, 0, 'f', 2), size(c.width_m), size(c.height_m),
             tr("%n station(s) measured", nullptr, c.stations_measured), QString()});
    item->setTextAlignment(kDeviation, Qt::AlignLeft | Qt::AlignVCenter);
  }
}

void MapSectionsPanel::select_station(double station_m) {
  if (!sections_) return;
  // The row clicked (a plate, a stretch to rescan) stands for this station: it stays selected.
  if (QTreeWidgetItem* current = tree_->currentItem()) {
    const QVariant at = current->data(kWhere, kStationRole);
    if (at.isValid() && std::abs(at.toDouble() - station_m) < 1e-9) return;
  }
  QTreeWidgetItem* best = nullptr;
  for (int i = 0; out_of_tolerance_ && i < out_of_tolerance_->childCount(); ++i) {
    QTreeWidgetItem* item = out_of_tolerance_->child(i);
    if (std::abs(item->data(kWhere, kStationRole).toDouble() - station_m) < 1e-6) best = item;
  }
  for (int i = 0; !best && i < sections_->childCount(); ++i) {
    QTreeWidgetItem* item = sections_->child(i);
    if (station_m >= item->data(kWhere, kFromRole).toDouble() && station_m <= item->data(kWhere, kToRole).toDouble())
      best = item;
  }
  const QSignalBlocker quiet(tree_);
  tree_->setCurrentItem(best);
}

int MapSectionsPanel::section_rows() const { return sections_ ? sections_->childCount() : 0; }
int MapSectionsPanel::note_rows() const { return notes_ ? notes_->childCount() : 0; }
int MapSectionsPanel::rescan_rows() const { return rescan_ ? rescan_->childCount() : 0; }
int MapSectionsPanel::out_of_tolerance_rows() const { return out_of_tolerance_ ? out_of_tolerance_->childCount() : 0; }

}  // namespace tunnelmap::ui
