#pragma once
// Tables of the report: a bold header with a rule, striped rows, wrapped text in the columns
// that allow it; the header repeats on every page the table continues on.
#include <QColor>
#include <QString>
#include <QStringList>
#include <vector>

#include "ui/report/report_document.h"

namespace tunnelmap::report {

struct Column {
  QString title;
  double weight = 1.0;  // share of the table width
  Qt::Alignment align = Qt::AlignRight;
  bool wrap = false;    // long text wraps (row grows) instead of running into the next cell
};

struct Row {
  QStringList cells;
  QColor colour = colours::kText;
};

struct TableStyle {
  double font_pt = 8.0;
  double width_fraction = 1.0;  // of the page width, left-aligned
};

void add_table(Document& doc, const std::vector<Column>& columns, const std::vector<Row>& rows,
               const TableStyle& style = {});

}  // namespace tunnelmap::report
