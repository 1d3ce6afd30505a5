#include "host/labsheet/lab_sheet_file.h"

#include <QBuffer>
#include <QFileInfo>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <cmath>

#include "core/files/atomic_file.h"
#include "host/labsheet/lab_sheet_painter.h"

namespace trilho {

namespace {
/// The PDF's own resolution: its coordinates are 1/600 in, four to a sheet pixel, so the curves
/// and the text are placed finer than the PNG's pixels (the PDF is vectors either way).
constexpr int kPdfDpi = 600;
}  // namespace

std::optional<LabSheetFormat> labSheetFormatFor(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("pdf")) return LabSheetFormat::Pdf;
    if (suffix == QLatin1String("png")) return LabSheetFormat::Png;
    return std::nullopt;
}

QByteArray labSheetPdf(const LabSheet& sheet) {
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter pdf(&buffer);
        pdf.setPageSize(QPageSize(QPageSize::A4));
        pdf.setPageOrientation(QPageLayout::Portrait);
        pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        pdf.setResolution(kPdfDpi);
        pdf.setTitle(QStringLiteral("Lab sheet %1").arg(labSheetDate(sheet)));
        pdf.setCreator(QStringLiteral("trilho"));
        QPainter p(&pdf);
        p.setRenderHint(QPainter::Antialiasing, true);
        p.scale(static_cast<double>(pdf.width()) / kLabSheetWidthPx,
                static_cast<double>(pdf.height()) / kLabSheetHeightPx);
        paintLabSheet(p, sheet);
        p.end();
    }
    return bytes;
}

QImage labSheetImage(const LabSheet& sheet) {
    QImage image(kLabSheetWidthPx, kLabSheetHeightPx, QImage::Format_RGB32);
    image.fill(Qt::white);
    const int dotsPerMetre = static_cast<int>(std::lround(kLabSheetDpi / 0.0254));
    image.setDotsPerMeterX(dotsPerMetre);
    image.setDotsPerMeterY(dotsPerMetre);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setRenderHint(QPainter::TextAntialiasing, true);
    paintLabSheet(p, sheet);
    p.end();
    return image;
}

QByteArray labSheetPng(const LabSheet& sheet) {
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    labSheetImage(sheet).save(&buffer, "PNG");
    return bytes;
}

bool writeLabSheet(const LabSheet& sheet, LabSheetFormat format, const QString& path,
                   QString* error) {
    const QByteArray bytes =
        format == LabSheetFormat::Pdf ? labSheetPdf(sheet) : labSheetPng(sheet);
    if (bytes.isEmpty()) {
        if (error)
            *error = QStringLiteral("cannot write '%1': the sheet could not be drawn").arg(path);
        return false;
    }
    return saveFileAtomically(path, bytes, error);
}

}  // namespace trilho
