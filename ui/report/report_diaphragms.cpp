#include "ui/report/report_diaphragms.h"

#include <algorithm>
#include <cmath>

#include "ui/report/report_format.h"
#include "ui/report/report_table.h"

namespace tunnelmap::report {

namespace {

Column num(const QString& title, double weight = 1.0) { return {title, weight, Qt::AlignRight}; }

// The narrowest clearance from the opening to a wall, "-" when no wall was measured (the sill's
// height above the floor is clearance_m[3]).
QString least_clearance(const Manhole& m) {
  double least = NAN;
  for (double c : m.clearance_m)
    if (std::isfinite(c)) least = std::isfinite(least) ? std::min(least, c) : c;
  return fixed(least, 3);
}

Row plate_row(std::size_t i, const Diaphragm& d) {
  Row r;
  const QString name = d.kind == "end_wall" ? QStringLiteral("end wall") : QStringLiteral("D%1").arg(i + 1);
  r.cells << name << fixed(d.station_m, 3) << QString::number(d.seen_by_frames);
  if (!d.manhole) {
    r.cells << QStringLiteral("-") << QStringLiteral("-") << QStringLiteral("-") << QStringLiteral("-")
            << QString::fromStdString(d.manhole_reason);
    return r;
  }
  const Manhole& m = *d.manhole;
  const QString shape = m.shape == "rounded_rectangle" ? QStringLiteral("rounded rectangle (r %1)").arg(fixed(m.corner_radius_m, 3))
                                                       : QString::fromStdString(m.shape);
  r.cells << metres(m.width_m) << metres(m.height_m) << fixed(m.clearance_m[3], 3) << least_clearance(m) << shape;
  return r;
}

// Which ends of a compartment are plates; an open end is where the observed extent stops.
QString ends(const Compartment& c) {
  const auto end = [](bool plate) { return plate ? QStringLiteral("plate") : QStringLiteral("open"); };
  return end(c.closed_from) + QStringLiteral(" – ") + end(c.closed_to);
}

}  // namespace

void add_compartments_table(Document& doc, const StationMap& m) {
  doc.add_heading(QStringLiteral("Compartments"));
  const std::vector<Compartment>& parts = m.girder.compartments;
  if (parts.empty()) {
    doc.add_paragraph(QStringLiteral("none: no stretch of the girder long enough for a station was observed"), doc.font(9.0),
                      colours::kMuted);
    return;
  }
  std::vector<Row> rows;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Compartment& c = parts[i];
    Row r;
    r.cells << QStringLiteral("C%1").arg(i + 1) << fixed(c.from_m, 3) << fixed(c.to_m, 3)
            << fixed(c.to_m - c.from_m, 3) << metres(c.width_m) << metres(c.height_m)
            << QString::number(c.stations_measured) << ends(c);
    rows.push_back(r);
  }
  const std::vector<Column> cols = {{QStringLiteral("Compartment"), 1.5, Qt::AlignLeft},
                                    num(QStringLiteral("From (m)")),
                                    num(QStringLiteral("To (m)")),
                                    num(QStringLiteral("Length (m)")),
                                    num(QStringLiteral("Width (m)")),
                                    num(QStringLiteral("Height (m)")),
                                    num(QStringLiteral("Stations measured"), 1.2),
                                    {QStringLiteral("Ends"), 1.3, Qt::AlignLeft}};
  add_table(doc, cols, rows);
  doc.add_paragraph(QStringLiteral("Width and height: medians of the stations measured inside the compartment, "
                                   "away from its plates; a dash where no station was measured."),
                    doc.font(8.0), colours::kMuted);
}

void add_diaphragms_table(Document& doc, const StationMap& m) {
  doc.add_heading(QStringLiteral("Diaphragms and manholes"));
  const std::vector<Diaphragm>& plates = m.girder.diaphragms;
  if (plates.empty()) {
    doc.add_paragraph(QStringLiteral("none: no plate across the girder was seen"), doc.font(9.0), colours::kMuted);
    return;
  }
  std::vector<Row> rows;
  for (std::size_t i = 0; i < plates.size(); ++i) rows.push_back(plate_row(i, plates[i]));
  const std::vector<Column> cols = {{QStringLiteral("Plate"), 0.8, Qt::AlignLeft},
                                    num(QStringLiteral("Station (m)")),
                                    num(QStringLiteral("Frames"), 0.9),
                                    num(QStringLiteral("Manhole width (m)"), 1.2),
                                    num(QStringLiteral("Manhole height (m)"), 1.2),
                                    num(QStringLiteral("Sill above floor (m)"), 1.2),
                                    num(QStringLiteral("Least clearance (m)"), 1.2),
                                    {QStringLiteral("Shape, or why not measured"), 2.6, Qt::AlignLeft, true}};
  add_table(doc, cols, rows);
}

}  // namespace tunnelmap::report
