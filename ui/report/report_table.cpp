#include "ui/report/report_table.h"

#include <algorithm>
#include <memory>
#include <numeric>

namespace tunnelmap::report {

namespace {

struct Layout {
  std::vector<double> x, w;  // left edge and width of each column (device pixels)
  double pad = 0.0;          // horizontal padding inside a cell
};

Layout layout_columns(const Document& doc, const std::vector<Column>& columns, double table_width) {
  Layout l;
  l.pad = doc.mm(1.2);
  const double total = std::accumulate(columns.begin(), columns.end(), 0.0,
                                       [](double s, const Column& c) { return s + c.weight; });
  double x = 0.0;
  for (const Column& c : columns) {
    l.x.push_back(x);
    l.w.push_back(table_width * c.weight / total);
    x += l.w.back();
  }
  return l;
}

// Draws `cells` in one row (`wrap[c]`: wrapping flags of cell c, 0 for one line); text is clipped
// to its cell so nothing overlaps its neighbour.
void draw_cells(QPainter& p, const QRectF& box, const Layout& l, const std::vector<Column>& columns,
                const QStringList& cells, const std::vector<int>& wrap, double vpad) {
  for (std::size_t c = 0; c < columns.size() && c < static_cast<std::size_t>(cells.size()); ++c) {
    const QRectF cell(box.left() + l.x[c] + l.pad, box.top() + vpad, l.w[c] - 2 * l.pad, box.height() - 2 * vpad);
    const int flags = static_cast<int>(columns[c].align | Qt::AlignTop) | wrap[c];
    p.save();
    p.setClipRect(cell.adjusted(0, -vpad, 0, vpad));
    p.drawText(cell, flags, cells[static_cast<int>(c)]);
    p.restore();
  }
}

}  // namespace

void add_table(Document& doc, const std::vector<Column>& columns, const std::vector<Row>& rows,
               const TableStyle& style) {
  const QFont body = doc.font(style.font_pt), bold = doc.font(style.font_pt, true);
  const double table_width = doc.width() * style.width_fraction;
  const Layout l = layout_columns(doc, columns, table_width);
  const double vpad = doc.mm(0.7), line = doc.metrics(body).height();
  const double rule = doc.mm(0.25), thin_rule = doc.mm(0.2);

  auto header = std::make_shared<Block>();
  {
    QStringList titles;
    std::vector<int> wrap;
    double h = line;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      titles << columns[c].title;
      wrap.push_back(doc.wrap_flags(columns[c].title, bold, l.w[c] - 2 * l.pad));
      h = std::max(h, doc.text_height(columns[c].title, bold, l.w[c] - 2 * l.pad));
    }
    header->height = h + 2 * vpad + doc.mm(0.4);
    header->paint = [=](QPainter& p, const QRectF& box) {
      p.setFont(bold);
      p.setPen(colours::kText);
      draw_cells(p, box, l, columns, titles, wrap, vpad);
      p.setPen(QPen(colours::kText, rule));
      p.drawLine(QPointF(box.left(), box.bottom() - rule),
                 QPointF(box.left() + table_width, box.bottom() - rule));
    };
  }

  for (std::size_t r = 0; r < rows.size(); ++r) {
    const Row& row = rows[r];
    double h = line;
    std::vector<int> wrap(columns.size(), 0);
    for (std::size_t c = 0; c < columns.size() && c < static_cast<std::size_t>(row.cells.size()); ++c) {
      if (!columns[c].wrap) continue;
      const QString& text = row.cells[static_cast<int>(c)];
      wrap[c] = doc.wrap_flags(text, body, l.w[c] - 2 * l.pad);
      h = std::max(h, doc.text_height(text, body, l.w[c] - 2 * l.pad));
    }
    Block b;
    b.height = h + 2 * vpad;
    b.header = header;
    b.first_row = r == 0;
    const bool stripe = r % 2 == 1;
    b.paint = [=](QPainter& p, const QRectF& box) {
      if (stripe) p.fillRect(QRectF(box.left(), box.top(), table_width, box.height()), colours::kStripe);
      p.setFont(body);
      p.setPen(row.colour);
      draw_cells(p, box, l, columns, row.cells, wrap, vpad);
    };
    doc.add(std::move(b));
  }
  // Closing rule under the last row.
  Block end;
  end.height = 3 * thin_rule;
  end.paint = [=](QPainter& p, const QRectF& box) {
    p.setPen(QPen(colours::kRule, thin_rule));
    p.drawLine(QPointF(box.left(), box.top() + thin_rule), QPointF(box.left() + table_width, box.top() + thin_rule));
  };
  doc.add(std::move(end));
}

}  // namespace tunnelmap::report
