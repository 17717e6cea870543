#include "ui/report/report_image.h"

#include <QImage>
#include <algorithm>

namespace tunnelmap::report {

void add_map_image(Document& doc, const std::string& png_path, const std::string& note) {
  doc.add_heading(QStringLiteral("Map"));
  const QString path = QString::fromStdString(png_path);
  QImage image;
  if (!png_path.empty() && !image.load(path)) {
    doc.add_paragraph(QStringLiteral("No image: ") + path + QStringLiteral(" could not be read."), doc.font(9.0),
                      colours::kMuted);
    return;
  }
  if (image.isNull()) {
    doc.add_paragraph(QStringLiteral("No image: ") +
                          (note.empty() ? QStringLiteral("none was rendered.") : QString::fromStdString(note)),
                      doc.font(9.0), colours::kMuted);
    return;
  }
  const QFont caption_font = doc.font(7.5);
  const QString caption = QStringLiteral(
      "The map mesh as rendered by tunnelmap-render, its roof and right wall left out to show the inside: "
      "traversable zones red, forbidden zones orange, plates grey with their manholes, the floor's and "
      "the left wall's boundaries thin blue lines.");
  const double caption_h = doc.text_height(caption, caption_font, doc.width()) + doc.mm(1.0);
  const double gap = doc.mm(1.5);
  // Whole width, never taller than most of a page; on a page with less room left it shrinks to
  // `min_height` rather than leave that room empty.
  const double aspect = static_cast<double>(image.height()) / std::max(1, image.width());
  const double full_h = std::min(doc.width() * aspect, doc.page_height() - doc.mm(25.0) - caption_h - gap);
  Block b;
  b.height = full_h + gap + caption_h;
  b.min_height = std::min(b.height, doc.mm(75.0) + gap + caption_h);
  b.paint = [=](QPainter& p, const QRectF& box) {
    const double h = box.height() - gap - caption_h, w = std::min(box.width(), h / aspect);
    const QRectF target(box.left() + 0.5 * (box.width() - w), box.top(), w, w * aspect);
    p.setRenderHint(QPainter::SmoothPixmapTransform, true);
    p.drawImage(target, image);
    p.setFont(caption_font);
    p.setPen(colours::kMuted);
    p.drawText(QRectF(box.left(), target.bottom() + gap, box.width(), caption_h),
               Qt::TextWordWrap | Qt::AlignHCenter | Qt::AlignTop, caption);
  };
  doc.add(std::move(b));
}

}  // namespace tunnelmap::report
