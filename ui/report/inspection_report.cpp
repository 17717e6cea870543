#include "ui/report/inspection_report.h"

#include <algorithm>
#include <fstream>
#include <QFontMetricsF>
#include <QMarginsF>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>

#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "ui/report/report_document.h"
#include "ui/report/report_image.h"
#include "ui/report/report_diaphragms.h"
#include "ui/report/report_lists.h"
#include "ui/report/report_overview.h"
#include "ui/report/report_plan.h"
#include "ui/report/report_profile.h"
#include "ui/report/report_qt_app.h"

#ifndef TUNNELMAP_VERSION
#define TUNNELMAP_VERSION "unknown"
#endif

namespace tunnelmap {

namespace {

constexpr int kDpi = 300;
constexpr double kFooterMm = 9.0;

void build(report::Document& doc, const InspectionReportInput& in) {
  using namespace report;
  const StationMap& m = *in.map;
  add_title_and_inputs(doc, in);
  add_summary(doc, m);
  add_notes(doc, in.notes);
  add_parameters(doc, in.params);
  if (m.stations.empty() && m.sections.empty()) {
    doc.add_heading(QStringLiteral("Plan and profiles"));
    doc.add_paragraph(QStringLiteral("Nothing to draw: the map has no stations."), doc.font(9.0), colours::kMuted);
  } else {
    doc.add_heading(QStringLiteral("Plan (top view, station along the tunnel axis)"));
    add_plan(doc, m);
    doc.add_heading(QStringLiteral("Width against station"));
    add_profile_plot(doc, m, Dimension::Width);
    doc.add_heading(QStringLiteral("Height against station"));
    add_profile_plot(doc, m, Dimension::Height);
  }
  add_sections_table(doc, m);
  add_diaphragms_table(doc, m);
  add_compartments_table(doc, m);
  add_out_of_tolerance_table(doc, m);
  add_rescan_table(doc, m);
  add_rescan_stretches_table(doc, m);
  add_map_image(doc, in.map_image_png, in.map_image_note);
}

// Footer: a rule, what the document is on the left, the page number on the right.
report::FooterFn footer_for(const report::Document& doc, const InspectionReportInput& in) {
  const QFont f = doc.font(7.0);
  const double rule = doc.mm(0.2), gap = doc.mm(2.5);
  const QString left = QStringLiteral("TunnelMap ") + QStringLiteral(TUNNELMAP_VERSION) +
                       QStringLiteral(" \u00b7 inspection report \u00b7 ") + QString::fromStdString(in.input);
  return [=](QPainter& p, const QRectF& box, int page, int pages) {
    const QFontMetricsF fm(f, p.device());
    const double top = box.top() + gap;
    p.setPen(QPen(report::colours::kRule, rule));
    p.drawLine(QPointF(box.left(), top), QPointF(box.right(), top));
    p.setFont(f);
    p.setPen(report::colours::kMuted);
    const QString right = QStringLiteral("page %1 of %2").arg(page).arg(pages);
    const double right_w = fm.horizontalAdvance(right);
    const QRectF text(box.left(), top + rule, box.width(), box.bottom() - top - rule);
    p.drawText(text, Qt::AlignRight | Qt::AlignVCenter, right);
    const QString elided = fm.elidedText(left, Qt::ElideMiddle, text.width() - right_w - gap);
    p.drawText(text, Qt::AlignLeft | Qt::AlignVCenter, elided);
  };
}

void paint_pdf(const std::string& pdf_path, const std::string& tmp_path, const InspectionReportInput& in) {
  const report::QuietQtWarnings quiet;
  QPdfWriter writer(QString::fromStdString(tmp_path));
  writer.setResolution(kDpi);
  writer.setPageSize(QPageSize(QPageSize::A4));
  writer.setPageMargins(QMarginsF(16, 14, 16, 10), QPageLayout::Millimeter);
  writer.setTitle(QStringLiteral("Tunnel inspection report: ") + QString::fromStdString(in.input));
  writer.setCreator(QStringLiteral("TunnelMap ") + QStringLiteral(TUNNELMAP_VERSION));
  QPainter painter;
  if (!painter.begin(&writer)) throw InputError(pdf_path, "cannot write: cannot create a file in that folder");
  report::Document doc(&writer, kFooterMm);
  build(doc, in);
  doc.render(painter, footer_for(doc, in));
  if (!painter.end()) throw InputError(pdf_path, "cannot write: the PDF could not be finished (disk full?)");
}

// Qt's PDF engine does not report failed writes (a full disk, a file size limit): the file it
// leaves then stops short of the trailer's "%%EOF", which is the last thing it writes.
bool ends_with_pdf_trailer(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in.tellg();
  if (!in || size < 8) return false;
  const std::streamoff tail = std::min<std::streamoff>(size, 32);
  std::string last(static_cast<std::size_t>(tail), '\0');
  in.seekg(size - tail);
  in.read(last.data(), tail);
  return in && last.find("%%EOF") != std::string::npos;
}

void write_pdf(const std::string& pdf_path, const std::string& tmp_path, const InspectionReportInput& in) {
  paint_pdf(pdf_path, tmp_path, in);  // the writer closes its file when it goes out of scope
  if (!ends_with_pdf_trailer(tmp_path))
    throw InputError(pdf_path, "cannot write: the PDF is incomplete (disk full?)");
}

}  // namespace

void write_inspection_report(const std::string& pdf_path, const InspectionReportInput& in) {
  if (!in.map) throw InputError(pdf_path, "cannot write the report: no station map given");
  check_output_path(pdf_path);
  try {
    report::ensure_gui_application();
    write_path_atomically(pdf_path, [&](const std::string& tmp) { write_pdf(pdf_path, tmp, in); });
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(pdf_path, std::string("cannot write the report: ") + e.what());
  }
}

}  // namespace tunnelmap
