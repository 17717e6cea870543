#include "ui/report/report_lists.h"

#include "core/mapping/rescan_stretches.h"
#include "ui/report/report_format.h"
#include "ui/report/report_table.h"

namespace tunnelmap::report {

namespace {

void add_none(Document& doc, const QString& text) {
  doc.add_paragraph(text, doc.font(9.0), colours::kMuted);
}

Column num(const QString& title, double weight = 1.0) { return {title, weight, Qt::AlignRight}; }

}  // namespace

void add_sections_table(Document& doc, const StationMap& m) {
  doc.add_heading(QStringLiteral("Sections"));
  if (m.sections.empty()) {
    add_none(doc, QStringLiteral("none: no stretch of constant cross-section was found"));
    return;
  }
  const auto& o = m.options;
  const bool design = o.design_width_m || o.design_height_m;
  std::vector<Column> cols = {{QStringLiteral("Section"), 0.8, Qt::AlignLeft},
                              num(QStringLiteral("From (m)")), num(QStringLiteral("To (m)")),
                              num(QStringLiteral("Length (m)")), num(QStringLiteral("Width (m)")),
                              num(QStringLiteral("Height (m)")), num(QStringLiteral("Frames"), 0.8)};
  if (design) {
    cols.push_back(num(QStringLiteral("\u0394 width (mm)")));
    cols.push_back(num(QStringLiteral("\u0394 height (mm)")));
  }
  std::vector<Row> rows;
  for (std::size_t i = 0; i < m.sections.size(); ++i) {
    const Section& s = m.sections[i];
    Row r;
    r.cells << QStringLiteral("S%1").arg(i + 1) << fixed(s.from_m, 2) << fixed(s.to_m, 2)
            << fixed(s.to_m - s.from_m, 2) << metres(s.width_m) << metres(s.height_m) << QString::number(s.frames);
    if (design) {
      const auto dw = deviation_mm(s.width_m, o.design_width_m), dh = deviation_mm(s.height_m, o.design_height_m);
      r.cells << signed_mm(dw) << signed_mm(dh);
      if (beyond_tolerance(dw, o.tolerance_mm) || beyond_tolerance(dh, o.tolerance_mm)) r.colour = colours::kAlert;
    }
    rows.push_back(r);
  }
  add_table(doc, cols, rows);
  if (design)
    doc.add_paragraph(QStringLiteral("\u0394: section value minus design; red: beyond \u00b1 %1 mm.")
                          .arg(o.tolerance_mm),
                      doc.font(7.5), colours::kMuted);
}

void add_out_of_tolerance_table(Document& doc, const StationMap& m) {
  doc.add_heading(QStringLiteral("Stations out of tolerance"));
  const auto& o = m.options;
  if (!o.design_width_m && !o.design_height_m) {
    add_none(doc, QStringLiteral("none: no design cross-section was given, so nothing was checked"));
    return;
  }
  std::vector<Row> rows;
  for (const Station& s : m.stations) {
    if (!s.out_of_tolerance) continue;
    const auto dw = s.width_dev_mm ? s.width_dev_mm
                                   : (s.width_source == DimensionSource::Unseen ? std::nullopt
                                                                                : deviation_mm(s.width_m, o.design_width_m));
    const auto dh = s.height_dev_mm ? s.height_dev_mm
                                    : (s.height_source == DimensionSource::Unseen ? std::nullopt
                                                                                  : deviation_mm(s.height_m, o.design_height_m));
    Row r;
    r.cells << fixed(s.station_m, 2)
            << (s.width_source == DimensionSource::Unseen ? QStringLiteral("-") : metres(s.width_m))
            << (s.height_source == DimensionSource::Unseen ? QStringLiteral("-") : metres(s.height_m))
            << signed_mm(dw) << signed_mm(dh) << source_label(s.width_source) << source_label(s.height_source)
            << QString::number(s.frames);
    rows.push_back(r);
  }
  if (rows.empty()) {
    add_none(doc, QStringLiteral("none: every station is within \u00b1 %1 mm of the design").arg(o.tolerance_mm));
    return;
  }
  const std::vector<Column> cols = {num(QStringLiteral("Station (m)")), num(QStringLiteral("Width (m)")),
                                    num(QStringLiteral("Height (m)")), num(QStringLiteral("\u0394 width (mm)")),
                                    num(QStringLiteral("\u0394 height (mm)")),
                                    {QStringLiteral("Width from"), 1.0, Qt::AlignHCenter},
                                    {QStringLiteral("Height from"), 1.0, Qt::AlignHCenter},
                                    num(QStringLiteral("Frames"), 0.7)};
  add_table(doc, cols, rows);
}

void add_rescan_table(Document& doc, const StationMap& m) {
  doc.add_heading(QStringLiteral("Poses to rescan"));
  std::vector<Row> rows;
  for (const PoseGroupStatus& p : m.poses) {
    if (!p.rescan) continue;
    Row r;
    const double station = m.station_of(p.camera_to_world.translation());
    r.cells << QStringLiteral("P%1").arg(p.group) << fixed(station, 2) << frame_list(p.frames)
            << QStringLiteral("%1 of %2").arg(p.detected_frames).arg(p.frames.size())
            << QString::fromStdString(p.message);
    rows.push_back(r);
  }
  if (rows.empty()) {
    add_none(doc, QStringLiteral("none: every pose found the tunnel"));
    return;
  }
  const std::vector<Column> cols = {{QStringLiteral("Pose"), 0.6, Qt::AlignLeft},
                                    num(QStringLiteral("Camera station (m)"), 1.2),
                                    {QStringLiteral("Frames"), 1.3, Qt::AlignLeft, true},
                                    num(QStringLiteral("Detected"), 0.9),
                                    {QStringLiteral("Message"), 4.0, Qt::AlignLeft, true}};
  add_table(doc, cols, rows);
}

void add_rescan_stretches_table(Document& doc, const StationMap& m) {
  doc.add_heading(QStringLiteral("Stretches to rescan"));
  std::vector<Row> rows;
  for (const RescanStretch& s : rescan_stretches(m)) {
    Row r;
    r.cells << fixed(s.from_m, 2) << fixed(s.to_m, 2) << fixed(s.to_m - s.from_m, 2)
            << QString::fromLatin1(station_dimension_name(s.dimension)) << QString::fromStdString(s.reason);
    if (s.joint_inside) r.colour = colours::kAlert;
    rows.push_back(r);
  }
  if (rows.empty()) {
    add_none(doc, QStringLiteral("none: no unmeasured stretch is long enough to hide a section or holds a joint"));
    return;
  }
  const std::vector<Column> cols = {num(QStringLiteral("From (m)")), num(QStringLiteral("To (m)")),
                                    num(QStringLiteral("Length (m)")),
                                    {QStringLiteral("Unmeasured"), 1.1, Qt::AlignHCenter},
                                    {QStringLiteral("Why"), 4.5, Qt::AlignLeft, true}};
  add_table(doc, cols, rows);
  doc.add_paragraph(QStringLiteral("Stations whose size no frame measured: filled from their neighbours or the "
                                   "design, or unknown; red: a joint lies somewhere in the stretch."),
                    doc.font(7.5), colours::kMuted);
}

}  // namespace tunnelmap::report
