#pragma once
// The two looks: "classic" replays the 1996 Visual Basic colours (screens.md: background
// &H00FF8080& = RGB 128,128,255, silver frames &H00C0C0C0&), "system" is the desktop's own.
#include <QColor>
#include <QString>

class QApplication;

namespace trilho {
namespace ui {

enum class Theme { Classic, System };

inline const QColor kClassicBackground{128, 128, 255};  ///< &H00FF8080& (VB colours are BGR)
inline const QColor kSilver{192, 192, 192};             ///< &H00C0C0C0&: frames, grey fields
inline const QColor kOnlineStatusText{0, 0, 128};       ///< dark blue letters
inline const QColor kDisabledText{128, 128, 128};       ///< VB's greyed caption (vbGrayText)

QString themeName(Theme t);
Theme themeFromName(const QString& name);
/// Applies the look to the whole application (palette and a small style sheet).
void applyTheme(QApplication& app, Theme theme);

}  // namespace ui
}  // namespace trilho
