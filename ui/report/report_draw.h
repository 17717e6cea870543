#pragma once
// Drawing pieces shared by the plan and the plots: markers, a one-row legend, the station
// ruler. Sizes are in device pixels; `mm` converts (Document::mm).
#include <QColor>
#include <QFont>
#include <QPainter>
#include <QString>
#include <functional>
#include <vector>

#include "ui/report/report_axis.h"
#include "ui/report/report_document.h"

namespace tunnelmap::report {

enum class Mark { Dot, HollowDot, TriangleUp, Line, DashedLine, Swatch, BandWithLine };

void draw_mark(QPainter& p, Mark m, const QPointF& centre, double size, const QColor& colour,
               const QColor& fill = Qt::transparent);

struct LegendItem {
  Mark mark;
  QColor colour;
  QString text;
  QColor fill = Qt::transparent;  // swatches and bands
};

// One row of legend items from the left of `row`, vertically centred.
void draw_legend(QPainter& p, const QRectF& row, const std::vector<LegendItem>& items, const QFont& f,
                 const std::function<double(double)>& mm);

// Ticks and labels (metres) of the station axis `x` below the line at `y`, a caption at the right
// end. Labels that would overlap the previous one are skipped.
void draw_station_ruler(QPainter& p, const Axis& x, double y, double step, const QFont& f,
                        const std::function<double(double)>& mm, bool with_caption);

}  // namespace tunnelmap::report
