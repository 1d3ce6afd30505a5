#pragma once
// A lab sheet (lab_sheet.h) as a file: a one-page A4 PDF through Qt's own PDF writer
// (QPdfWriter, Qt GUI: no printing module needed on the command line), or a PNG of the same
// page at 150 dpi. Either is written atomically (core/files/atomic_file.h): a full disk leaves
// the old file as it was and says so.
#include <QByteArray>
#include <QImage>
#include <QString>
#include <optional>

#include "host/labsheet/lab_sheet.h"

namespace trilho {

enum class LabSheetFormat { Pdf, Png };

/// The format a file name asks for by its extension (.pdf or .png, any case); none otherwise.
std::optional<LabSheetFormat> labSheetFormatFor(const QString& path);

/// The sheet as a PDF of one A4 page (its vector drawing, its text as text).
QByteArray labSheetPdf(const LabSheet& sheet);
/// The sheet as an image, kLabSheetWidthPx x kLabSheetHeightPx, 150 dpi, white paper.
QImage labSheetImage(const LabSheet& sheet);
QByteArray labSheetPng(const LabSheet& sheet);

/// Writes the sheet to path in format, atomically; false with *error naming the path and the
/// reason ("cannot write 'x.pdf': No space left on device"), the old file then untouched.
bool writeLabSheet(const LabSheet& sheet, LabSheetFormat format, const QString& path,
                   QString* error);

}  // namespace trilho
