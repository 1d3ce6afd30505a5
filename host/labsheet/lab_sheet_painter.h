#pragma once
// Draws a lab sheet (lab_sheet.h) on one A4 page, portrait: the title and the date, the
// machine and the model, the runs' responses overlaid (lab_sheet_plot.h), the table of their
// conditions and metrics side by side, and a line for the student's name. The page is
// kLabSheetWidthPx x kLabSheetHeightPx sheet pixels (A4 at 150 dpi); the PDF scales them to
// its own resolution, the PNG is them.
#include <QPainter>

#include "host/labsheet/lab_sheet.h"

namespace trilho {

inline constexpr int kLabSheetDpi = 150;
inline constexpr int kLabSheetWidthPx = 1240;   ///< 210 mm at 150 dpi
inline constexpr int kLabSheetHeightPx = 1754;  ///< 297 mm at 150 dpi

/// Paints the sheet with the painter's units as sheet pixels (the caller scales a device of
/// another resolution). The painter's state is restored.
void paintLabSheet(QPainter& p, const LabSheet& sheet);

}  // namespace trilho
