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

namespace {
/// A dead control must look dead: some palettes (the offscreen one, a hand-made one) paint the
/// Disabled group as the Active one, so the text roles get the grey the 1996 form used.
void greyDisabledText(QPalette& p) {
    for (QPalette::ColorRole role : {QPalette::WindowText, QPalette::ButtonText, QPalette::Text})
        if (p.color(QPalette::Disabled, role) == p.color(QPalette::Active, role))
            p.setColor(QPalette::Disabled, role, kDisabledText);
}
}  // namespace

void applyTheme(QApplication& app, Theme theme) {
    static const QPalette systemPalette = app.palette();
    if (theme == Theme::System) {
        QPalette p = systemPalette;
        greyDisabledText(p);
        app.setPalette(p);
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
    // setColor(role, c) above painted every group, Disabled too: grey it again as VB did.
    for (QPalette::ColorRole role : {QPalette::WindowText, QPalette::ButtonText, QPalette::Text})
        p.setColor(QPalette::Disabled, role, kDisabledText);
    p.setColor(QPalette::Disabled, QPalette::Base, kSilver);
    app.setPalette(p);
    // The execucao form's blue background; frames stay silver as VB frames were.
    app.setStyleSheet(QStringLiteral(
        "QWidget#executionPanel, QWidget#startScreen { background-color: rgb(128,128,255); }"
        "QGroupBox#vbFrame { background-color: rgb(192,192,192); border: 2px groove white; "
        "margin-top: 1em; }"
        "QGroupBox#vbFrame::title { subcontrol-origin: margin; left: 8px; padding: 0 3px; }"
        // The form's captions were bold, italic, underlined labels inside the silver boxes.
        "QGroupBox#vbFrame { font-weight: bold; font-style: italic; text-decoration: underline; }"
        "QLabel#vbCaption { color: black; }"
        "QWidget#executionPanel > QLabel { color: black; font-weight: bold; }"));
}

}  // namespace ui
}  // namespace trilho
