#include "host/labsheet/lab_sheet_painter.h"

#include <QFontMetricsF>
#include <algorithm>

#include "host/labsheet/lab_sheet_plot.h"

namespace trilho {

namespace {

constexpr double kMargin = 80.0;       ///< sheet pixels, about 13.5 mm: inside any printer's margin
constexpr double kPlotHeight = 440.0;  ///< the responses
constexpr double kDriveHeight = 210.0;  ///< the drive below them
constexpr int kTableFontPx = 16;        ///< the table's type when it fits
constexpr int kTableMinFontPx = 9;      ///< smaller than this no one reads it printed

constexpr int kCellFlags = Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap;

/// How a cell's text wraps: at its spaces, or anywhere when a word of it (a file's path, a
/// date) is wider than the cell, so nothing is cut off at the cell's edge.
int cellFlags(const QFontMetricsF& fm, const QString& text, double width) {
    for (const QString& word : text.split(QLatin1Char(' '), Qt::SkipEmptyParts))
        if (fm.horizontalAdvance(word) > width)
            return Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWrapAnywhere;
    return kCellFlags;
}

/// The table's geometry at one type size.
struct TableLayout {
    int fontPx = kTableFontPx;
    double nameW = 0.0, colW = 0.0;
    double headerH = 0.0;
    std::vector<double> rowH;
    double height() const {
        double h = headerH;
        for (const double r : rowH)
            h += r;
        return h;
    }
};

TableLayout layoutTable(const LabSheet& sheet, const std::vector<LabSheetRow>& rows, double width,
                        int fontPx, QPaintDevice* device) {
    TableLayout t;
    t.fontPx = fontPx;
    const QFontMetricsF fm(labSheetFont(fontPx), device);
    const QFontMetricsF bm(labSheetFont(fontPx, true), device);
    for (const LabSheetRow& row : rows)  // the names are drawn bold
        t.nameW = std::max(t.nameW, bm.horizontalAdvance(row.name));
    t.nameW += 16.0;
    const double n = static_cast<double>(std::max<std::size_t>(sheet.runs.size(), 1));
    t.colW = (width - t.nameW) / n;
    const double pad = 0.45 * fm.height();
    auto cellH = [&](const QFontMetricsF& m, const QString& text) {
        const double w = t.colW - 12.0;
        return m.boundingRect(QRectF(0, 0, w, 1e6), cellFlags(m, text, w), text).height() + pad;
    };
    t.headerH = 0.0;
    for (const LabSheetRun& run : sheet.runs)
        t.headerH = std::max(t.headerH, cellH(bm, run.label));
    for (const LabSheetRow& row : rows) {
        double h = fm.height() + pad;
        for (const QString& cell : row.cells)
            h = std::max(h, cellH(fm, cell));
        t.rowH.push_back(h);
    }
    return t;
}

void paintTable(QPainter& p, const QRectF& area, const LabSheet& sheet) {
    const std::vector<LabSheetRow> rows = labSheetRows(sheet);
    // The largest type at which the whole table fits its room; at the smallest it is cut.
    TableLayout t;
    for (int px = kTableFontPx; px >= kTableMinFontPx; --px) {
        t = layoutTable(sheet, rows, area.width(), px, p.device());
        if (t.height() <= area.height()) break;
    }
    p.save();
    p.setClipRect(area);
    const QFont font = labSheetFont(t.fontPx), bold = labSheetFont(t.fontPx, true);
    const QFontMetricsF fm(font, p.device()), bm(bold, p.device());
    const QColor ink(30, 30, 30);
    double y = area.top();
    // Heading: each run's label in its colour.
    p.setFont(bold);
    for (std::size_t c = 0; c < sheet.runs.size(); ++c) {
        const QRectF cell(area.left() + t.nameW + t.colW * static_cast<double>(c), y, t.colW,
                          t.headerH);
        p.fillRect(QRectF(cell.left() + 2, cell.bottom() - 5, cell.width() - 4, 4),
                   sheet.runs[c].color);
        p.setPen(sheet.runs[c].color.darker(120));
        p.drawText(cell.adjusted(6, 0, -6, -6), cellFlags(bm, sheet.runs[c].label, t.colW - 12),
                   sheet.runs[c].label);
    }
    y += t.headerH;
    bool shade = false;
    bool metricsBegun = false;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const LabSheetRow& row = rows[r];
        const double h = t.rowH[r];
        if (row.metric && !metricsBegun) {
            metricsBegun = true;
            p.setPen(QPen(QColor(90, 90, 90), 1.5));
            p.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
            shade = false;
        }
        if (shade) p.fillRect(QRectF(area.left(), y, area.width(), h), QColor(242, 242, 242));
        shade = !shade;
        p.setPen(ink);
        p.setFont(bold);
        p.drawText(QRectF(area.left() + 4, y, t.nameW - 8, h), kCellFlags, row.name);
        p.setFont(font);
        for (std::size_t c = 0; c < row.cells.size(); ++c)
            p.drawText(QRectF(area.left() + t.nameW + t.colW * static_cast<double>(c) + 6, y,
                              t.colW - 12, h),
                       cellFlags(fm, row.cells[c], t.colW - 12), row.cells[c]);
        y += h;
    }
    p.setPen(QPen(QColor(90, 90, 90), 1.5));
    p.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
    p.restore();
}

}  // namespace

void paintLabSheet(QPainter& p, const LabSheet& sheet) {
    p.save();
    const double left = kMargin, right = kLabSheetWidthPx - kMargin;
    const double width = right - left;
    const QColor ink(30, 30, 30), grey(100, 100, 100);

    // Title, and the date on its right.
    double y = 64.0;
    p.setPen(ink);
    p.setFont(labSheetFont(34, true));
    const QFontMetricsF tm(p.font(), p.device());
    p.drawText(QRectF(left, y, width, tm.height()), Qt::AlignLeft | Qt::AlignVCenter,
               QStringLiteral("Lab sheet: step responses"));
    p.setFont(labSheetFont(18));
    p.drawText(QRectF(left, y, width, tm.height()), Qt::AlignRight | Qt::AlignVCenter,
               labSheetDate(sheet));
    y += tm.height() + 10;
    p.setPen(QPen(ink, 2));
    p.drawLine(QPointF(left, y), QPointF(right, y));
    y += 12;

    // Machine and model.
    const QFont label = labSheetFont(18, true), body = labSheetFont(18);
    const QFontMetricsF bm(body, p.device());
    auto line = [&](const QString& name, const QString& text) {
        p.setFont(label);
        const double nameW =
            QFontMetricsF(label, p.device()).horizontalAdvance(name + QLatin1Char(' '));
        p.drawText(QRectF(left, y, nameW, bm.height()), Qt::AlignLeft | Qt::AlignVCenter, name);
        p.setFont(body);
        const QRectF rest(left + nameW, y, width - nameW, bm.height() * 2);
        const QRectF used =
            p.boundingRect(rest, Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, text);
        p.drawText(rest, Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, text);
        y += std::max(bm.height(), std::min(used.height(), rest.height())) + 4;
    };
    p.setPen(ink);
    line(QStringLiteral("Machine:"), labSheetMachines(sheet));
    line(QStringLiteral("Model:"), sheet.model.isEmpty()
                                       ? QStringLiteral("none identified for these runs (the "
                                                        "workbench's Identify, or tune identify)")
                                       : sheet.model);
    y += 8;

    // The runs overlaid: their responses, and below the drive their loops wrote.
    paintLabSheetPlot(p, QRectF(left, y, width, kPlotHeight), sheet, LabSheetChannel::Position);
    y += kPlotHeight + 4;
    paintLabSheetPlot(p, QRectF(left, y, width, kDriveHeight), sheet, LabSheetChannel::Drive);
    y += kDriveHeight + 18;

    // The table to the footer.
    const double footerTop = kLabSheetHeightPx - kMargin - 70.0;
    paintTable(p, QRectF(left, y, width, footerTop - 14 - y), sheet);

    // The student's line and where the sheet came from.
    p.setPen(ink);
    p.setFont(body);
    p.drawText(QRectF(left, footerTop, width, bm.height()), Qt::AlignLeft | Qt::AlignVCenter,
               QStringLiteral("Name: ______________________________   Group: ________   "
                              "Date handed in: ______________"));
    p.setPen(grey);
    p.setFont(labSheetFont(13));
    p.drawText(QRectF(left, footerTop + bm.height() + 14, width, 40),
               Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap,
               QStringLiteral("Made by trilho. The metrics are those `trilho-cli tune metrics` "
                              "prints of each run's trace: rise 10-90 %, settling within 2 % and "
                              "within one encoder count, from the step's command."));
    p.restore();
}

}  // namespace trilho
