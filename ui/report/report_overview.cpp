#include "ui/report/report_overview.h"

#include <QDateTime>
#include <cmath>

#include "ui/report/report_format.h"
#include "ui/report/report_table.h"

#ifndef TUNNELMAP_VERSION
#define TUNNELMAP_VERSION "unknown"
#endif

namespace tunnelmap::report {

namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

struct SourceCounts {
  int measured = 0, context = 0, design = 0, unseen = 0;
  void add(DimensionSource s) {
    switch (s) {
      case DimensionSource::Measured: ++measured; break;
      case DimensionSource::Context: ++context; break;
      case DimensionSource::Design: ++design; break;
      case DimensionSource::Unseen: ++unseen; break;
    }
  }
  QString text() const {
    return QStringLiteral("%1 measured, %2 from context, %3 from design, %4 unseen")
        .arg(measured).arg(context).arg(design).arg(unseen);
  }
};

QString json_value_text(const nlohmann::json& v) {
  if (v.is_string()) return q(v.get<std::string>());
  // Six significant digits: parameters are set at human precision, and 0.1 * 3 must not print
  // as 0.30000000000000004.
  if (v.is_number_float()) return QString::number(v.get<double>(), 'g', 6);
  return q(v.dump());
}

}  // namespace

void add_title_and_inputs(Document& doc, const InspectionReportInput& in) {
  const StationMap& m = *in.map;
  const QFont title = doc.font(18.0, true);
  Block t;
  t.height = doc.metrics(title).height() + doc.mm(2.0);
  t.paint = [title](QPainter& p, const QRectF& box) {
    p.setFont(title);
    p.setPen(colours::kAccent);
    p.drawText(box, Qt::AlignLeft | Qt::AlignTop, QStringLiteral("Tunnel inspection report"));
  };
  doc.add(std::move(t));
  doc.add_space(1.5);

  const QString created = in.created.empty()
                              ? QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"))
                              : q(in.created);
  std::vector<std::pair<QString, QString>> rows = {
      {QStringLiteral("Input"), in.input.empty() ? QStringLiteral("-") : q(in.input)},
      {QStringLiteral("Created"), created},
      {QStringLiteral("Tool"), QStringLiteral("TunnelMap ") + QStringLiteral(TUNNELMAP_VERSION)},
      {QStringLiteral("Station step"), fixed(m.options.station_step_m, 3) + QStringLiteral(" m")},
      {QStringLiteral("Design"), design_text(m.options)},
      {QStringLiteral("Tolerance"),
       QStringLiteral("\u00b1 %1 mm on width and on height").arg(m.options.tolerance_mm) +
           (m.options.design_width_m || m.options.design_height_m ? QString()
                                                                  : QStringLiteral(" (no design to check against)"))},
      {QStringLiteral("Section change"),
       QStringLiteral("%1 mm over at least %2 stations").arg(m.options.section_change_mm).arg(m.options.min_section_stations)},
  };
  doc.add_key_values(rows, 32.0);
}

void add_summary(Document& doc, const StationMap& m) {
  doc.add_heading(QStringLiteral("Summary"));
  std::vector<std::pair<QString, QString>> rows;
  if (!m.ok) {
    rows.push_back({QStringLiteral("Map"), QStringLiteral("not built: ") + q(m.status) +
                                               (m.reason.empty() ? QString() : QStringLiteral(" (") + q(m.reason) + ")")});
  }
  if (!m.stations.empty()) {
    const double half = 0.5 * m.options.station_step_m;
    const double from = m.stations.front().station_m - half, to = m.stations.back().station_m + half;
    rows.push_back({QStringLiteral("Observed extent"), QStringLiteral("%1 m to %2 m (%3 m)")
                                                           .arg(fixed(from, 2), fixed(to, 2), fixed(to - from, 2))});
  } else {
    rows.push_back({QStringLiteral("Observed extent"), QStringLiteral("none")});
  }
  SourceCounts widths, heights;
  int beyond = 0;
  for (const Station& s : m.stations) {
    widths.add(s.width_source);
    heights.add(s.height_source);
    if (s.out_of_tolerance) ++beyond;
  }
  rows.push_back({QStringLiteral("Stations"), QStringLiteral("%1, every %2 m").arg(m.stations.size()).arg(fixed(m.options.station_step_m, 2))});
  rows.push_back({QStringLiteral("  width"), widths.text()});
  rows.push_back({QStringLiteral("  height"), heights.text()});
  rows.push_back({QStringLiteral("Sections"), QString::number(m.sections.size())});
  const bool design = m.options.design_width_m || m.options.design_height_m;
  rows.push_back({QStringLiteral("Out of tolerance"),
                  design ? QStringLiteral("%1 of %2 stations").arg(beyond).arg(m.stations.size())
                         : QStringLiteral("not checked (no design)")});
  int rescan = 0;
  for (const PoseGroupStatus& p : m.poses) rescan += p.rescan ? 1 : 0;
  rows.push_back({QStringLiteral("Poses to rescan"), QStringLiteral("%1 of %2").arg(rescan).arg(m.poses.size())});
  rows.push_back({QStringLiteral("Frames used"), QStringLiteral("%1 of %2").arg(m.frames_used).arg(m.frames)});
  doc.add_key_values(rows, 32.0);
}

void add_notes(Document& doc, const std::vector<std::string>& notes) {
  if (notes.empty()) return;
  doc.add_heading(QStringLiteral("Notes"));
  for (const std::string& note : notes) doc.add_paragraph(q(note), doc.font(9.0), colours::kText);
}

void add_parameters(Document& doc, const nlohmann::json& params) {
  doc.add_heading(QStringLiteral("Parameters"));
  std::vector<std::pair<QString, QString>> kv;
  if (params.is_object())
    for (auto it = params.begin(); it != params.end(); ++it) kv.push_back({q(it.key()), json_value_text(it.value())});
  if (kv.empty()) {
    doc.add_paragraph(params.is_null() || params.empty() ? QStringLiteral("none given") : q(params.dump()),
                      doc.font(8.0));
    return;
  }
  // Column-major: the first half down the left pair of columns, the rest down the right pair.
  const std::size_t half = (kv.size() + 1) / 2;
  std::vector<Row> rows;
  for (std::size_t i = 0; i < half; ++i) {
    Row r;
    r.cells << kv[i].first << kv[i].second;
    if (i + half < kv.size()) r.cells << kv[i + half].first << kv[i + half].second;
    rows.push_back(r);
  }
  // Long keys or text values wrap rather than run under the next column.
  const std::vector<Column> columns = {{QStringLiteral("key"), 3.2, Qt::AlignLeft, true},
                                       {QStringLiteral("value"), 1.3, Qt::AlignLeft, true},
                                       {QStringLiteral("key"), 3.2, Qt::AlignLeft, true},
                                       {QStringLiteral("value"), 1.3, Qt::AlignLeft, true}};
  TableStyle style;
  style.font_pt = 7.0;
  add_table(doc, columns, rows, style);
}

}  // namespace tunnelmap::report
