#include "ui/theme.h"

#include <QApplication>
#include <QPalette>
#include <QStyle>
#include <QStyleFactory>

namespace trilho {
namespace ui {

QString themeName(Theme t) {
    return t == Theme::Classic ? QStringLiteral("classic") : QStringLiteral("system");
}

Theme themeFromName(const QString& name) {
    return name == QLatin1String("system") ? Theme::System : Theme::Classic;
}

void applyTheme(QApplication& app, Theme theme) {
    static const QPalette systemPalette = app.palette();
    if (theme == Theme::System) {
        app.setPalette(systemPalette);
        app.setStyleSheet(QString());
        return;
    }
    app.setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QPalette p = app.style()->standardPalette();
    p.setColor(QPalette::Window, kSilver);
    p.setColor(QPalette::Button, kSilver);
    p.setColor(QPalette::Base, Qt::white);
    p.setColor(QPalette::WindowText, Qt::black);
    p.setColor(QPalette::ButtonText, Qt::black);
    p.setColor(QPalette::Text, Qt::black);
    p.setColor(QPalette::Highlight, QColor(0, 0, 128));
    p.setColor(QPalette::HighlightedText, Qt::white);
    app.setPalette(p);
    // The execucao form's blue background; frames stay silver as VB frames were.
    app.setStyleSheet(QStringLiteral(
        "QWidget#executionPanel, QWidget#startScreen { background-color: rgb(128,128,255); }"
        "QGroupBox#vbFrame { background-color: rgb(192,192,192); border: 2px groove white; "
        "margin-top: 1.2em; }"
        "QGroupBox#vbFrame::title { subcontrol-origin: margin; left: 8px; padding: 0 3px; }"
        "QLabel#vbCaption { color: black; }"
        "QWidget#executionPanel > QLabel { color: black; font-weight: bold; }"));
}

}  // namespace ui
}  // namespace trilho
