#include "ui/report/report_document.h"

#include <QRegularExpression>
#include <algorithm>

namespace tunnelmap::report {

Document::Document(QPagedPaintDevice* device, double footer_mm) : device_(device) {
  dpi_ = device->logicalDpiY();
  width_ = device->width();
  footer_height_ = mm(footer_mm);
  body_height_ = device->height() - footer_height_;
}

QFont Document::font(double point_size, bool bold) const {
  QFont f(QStringLiteral("DejaVu Sans"));
  f.setStyleHint(QFont::SansSerif);
  f.setPointSizeF(point_size);
  f.setBold(bold);
  return f;
}

int Document::wrap_flags(const QString& text, const QFont& f, double width) const {
  const QFontMetricsF fm = metrics(f);
  for (const QString& word : text.split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts))
    if (fm.horizontalAdvance(word) > width) return Qt::TextWrapAnywhere;
  return Qt::TextWordWrap;
}

double Document::text_height(const QString& text, const QFont& f, double width) const {
  const QRectF r = metrics(f).boundingRect(QRectF(0, 0, width, 1e6), wrap_flags(text, f, width), text);
  return std::max(r.height(), metrics(f).height());
}

void Document::add_space(double mm_height) {
  Block b;
  b.height = mm(mm_height);
  b.spacing = true;
  b.paint = [](QPainter&, const QRectF&) {};
  add(std::move(b));
}

void Document::add_heading(const QString& text) {
  const QFont f = font(11.5, true);
  Block b;
  b.height = metrics(f).height() + mm(3.5);
  b.keep_with_next = true;
  b.paint = [f, text, gap = mm(1.0)](QPainter& p, const QRectF& box) {
    p.setFont(f);
    p.setPen(colours::kAccent);
    const QRectF text_box(box.left(), box.top() + 2 * gap, box.width(), box.height() - 3 * gap);
    p.drawText(text_box, Qt::AlignLeft | Qt::AlignVCenter, text);
    p.setPen(QPen(colours::kAccent, gap * 0.25));
    p.drawLine(QPointF(box.left(), box.bottom() - gap * 0.5), QPointF(box.right(), box.bottom() - gap * 0.5));
  };
  add(std::move(b));
}

void Document::add_paragraph(const QString& text, const QFont& f, const QColor& colour) {
  Block b;
  b.height = text_height(text, f, width_) + mm(1.0);
  const int wrap = wrap_flags(text, f, width_);
  b.paint = [f, text, colour, wrap](QPainter& p, const QRectF& box) {
    p.setFont(f);
    p.setPen(colour);
    p.drawText(box, wrap | Qt::AlignLeft | Qt::AlignTop, text);
  };
  add(std::move(b));
}

void Document::add_key_values(const std::vector<std::pair<QString, QString>>& rows, double label_mm) {
  const QFont label_font = font(9.0, true), value_font = font(9.0);
  const double label_w = mm(label_mm), value_w = width_ - label_w;
  for (const auto& [label, value] : rows) {
    Block b;
    b.height = std::max(text_height(value, value_font, value_w), metrics(label_font).height()) + mm(0.8);
    const int wrap = wrap_flags(value, value_font, value_w);
    b.paint = [=](QPainter& p, const QRectF& box) {
      p.setFont(label_font);
      p.setPen(colours::kMuted);
      p.drawText(QRectF(box.left(), box.top(), label_w, box.height()), Qt::AlignLeft | Qt::AlignTop, label);
      p.setFont(value_font);
      p.setPen(colours::kText);
      p.drawText(QRectF(box.left() + label_w, box.top(), value_w, box.height()), wrap | Qt::AlignLeft | Qt::AlignTop,
                 value);
    };
    add(std::move(b));
  }
}

void Document::start_new_page() {
  Block b;
  b.new_page = true;
  b.paint = [](QPainter&, const QRectF&) {};
  add(std::move(b));
}

std::vector<Document::Placed> Document::paginate(int& pages) const {
  std::vector<Placed> placed;
  int page = 1;
  double y = 0.0;
  auto header_height = [](const Block& b) { return b.header ? b.header->height : 0.0; };
  auto least_height = [](const Block& b) { return b.min_height > 0.0 ? b.min_height : b.height; };
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    const Block& b = blocks_[i];
    if (b.new_page && y > 0.0) {
      ++page;
      y = 0.0;
    }
    // A heading (or a run of them) needs the first following content block on the same page.
    double need = least_height(b) + (b.first_row ? header_height(b) : 0.0);
    for (std::size_t j = i; j + 1 < blocks_.size() && blocks_[j].keep_with_next; ++j)
      need += least_height(blocks_[j + 1]) + header_height(blocks_[j + 1]);
    if (y > 0.0 && y + need > body_height_) {
      ++page;
      y = 0.0;
    }
    if (b.spacing && y == 0.0) continue;
    if (b.header && (b.first_row || y == 0.0)) {
      placed.push_back({b.header.get(), page, y, b.header->height});
      y += b.header->height;
    }
    const double height = std::min(b.height, std::max(least_height(b), body_height_ - y));
    placed.push_back({&b, page, y, height});
    y += height;
  }
  pages = page;
  return placed;
}

int Document::render(QPainter& p, const FooterFn& footer) {
  int pages = 1;
  const std::vector<Placed> placed = paginate(pages);
  int page = 1;
  auto finish_page = [&] {
    p.save();
    footer(p, QRectF(0, body_height_, width_, footer_height_), page, pages);
    p.restore();
  };
  for (const Placed& pl : placed) {
    while (pl.page > page) {
      finish_page();
      device_->newPage();
      ++page;
    }
    p.save();
    pl.block->paint(p, QRectF(0, pl.y, width_, pl.height));
    p.restore();
  }
  while (page <= pages) {  // also the last page (and pages that only held spacing)
    finish_page();
    if (page == pages) break;
    device_->newPage();
    ++page;
  }
  return pages;
}

}  // namespace tunnelmap::report
