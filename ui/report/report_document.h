#pragma once
// A report as a list of blocks of known height laid out top to bottom over pages. Pagination
// happens before painting, so every page's footer knows the page count, a heading never ends a
// page and a table row that starts a page repeats its table's header.
#include <QFont>
#include <QFontMetricsF>
#include <QPagedPaintDevice>
#include <QPainter>
#include <QString>
#include <functional>
#include <memory>
#include <vector>

namespace tunnelmap::report {

// Paints a block into `box` (page coordinates, device pixels).
using PaintFn = std::function<void(QPainter& p, const QRectF& box)>;
// Paints the footer of page `page` (1-based) of `pages` into `box`.
using FooterFn = std::function<void(QPainter& p, const QRectF& box, int page, int pages)>;

struct Block {
  double height = 0.0;  // device pixels; never taller than a page
  PaintFn paint;
  std::shared_ptr<const Block> header;  // table rows: the table's header, painted above the
                                        // first row and again when a row starts a page
  bool first_row = false;               // the first row of its table
  bool keep_with_next = false;          // headings: moved to the next page with what follows
  bool new_page = false;                // start on a fresh page
  bool spacing = false;                 // vertical space: dropped at the top of a page
  double min_height = 0.0;              // > 0: may shrink to this to end the current page
                                        // instead of starting a new one (images)
};

// Colours shared by the text and the plots.
namespace colours {
inline const QColor kText{25, 25, 25};
inline const QColor kMuted{105, 105, 105};
inline const QColor kRule{170, 170, 170};
inline const QColor kStripe{242, 244, 247};
inline const QColor kAccent{31, 78, 140};
inline const QColor kAlert{200, 30, 30};
}  // namespace colours

class Document {
 public:
  // `device` is the PDF writer: it gives the resolution and font metrics.
  Document(QPagedPaintDevice* device, double footer_mm);

  double mm(double v) const { return v * dpi_ / 25.4; }
  double width() const { return width_; }
  double page_height() const { return body_height_; }  // room for blocks on one page
  QFont font(double point_size, bool bold = false) const;
  QFontMetricsF metrics(const QFont& f) const { return QFontMetricsF(f, device_); }
  // Wrapping flags for `text` in `width`: at word boundaries, or anywhere when one word (a long
  // path) is wider than `width`, so that nothing runs past its box.
  int wrap_flags(const QString& text, const QFont& f, double width) const;
  // Height of `text` wrapped (wrap_flags) into `width` device pixels.
  double text_height(const QString& text, const QFont& f, double width) const;

  void add(Block b) { blocks_.push_back(std::move(b)); }
  void add_space(double mm_height);
  void add_heading(const QString& text);
  // Wrapped text over the full width.
  void add_paragraph(const QString& text, const QFont& f, const QColor& colour = colours::kText);
  // "label  value" lines, labels in a column `label_mm` wide, values wrapped.
  void add_key_values(const std::vector<std::pair<QString, QString>>& rows, double label_mm);
  void start_new_page();

  // Paginates and paints every page (calling device->newPage() between pages). Returns the
  // number of pages.
  int render(QPainter& p, const FooterFn& footer);

 private:
  struct Placed {
    const Block* block;
    int page;
    double y, height;
  };
  std::vector<Placed> paginate(int& pages) const;

  QPagedPaintDevice* device_;
  double dpi_ = 300.0;
  double width_ = 0.0, body_height_ = 0.0, footer_height_ = 0.0;
  std::vector<Block> blocks_;
};

}  // namespace tunnelmap::report
