#include "ui/plot_legend.h"

#include <qcustomplot.h>

namespace trilho::ui {

void placeLegendAbove(QCustomPlot* p) {
    QFont small = p->font();
    small.setPointSizeF(small.pointSizeF() * 0.8);
    p->legend->setFont(small);
    p->legend->setBrush(Qt::NoBrush);
    p->legend->setBorderPen(Qt::NoPen);
    p->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);  // one row
    p->legend->setRowSpacing(0);
    p->legend->setColumnSpacing(12);
    // Out of the axis rect's inset layout into a row of the plot's own layout, above it.
    if (p->axisRect()->insetLayout()->take(p->legend)) p->axisRect()->insetLayout()->simplify();
    p->plotLayout()->insertRow(0);
    p->plotLayout()->addElement(0, 0, p->legend);
    p->plotLayout()->setRowStretchFactor(0, 0.001);  // as tall as the legend, no more
    p->plotLayout()->setRowSpacing(0);
    p->legend->setMargins(QMargins(4, 1, 4, 0));
    p->legend->setVisible(true);
}

}  // namespace trilho::ui
