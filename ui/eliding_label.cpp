#include "ui/eliding_label.h"

#include <QEvent>
#include <QFontMetrics>
#include <algorithm>

namespace trilho::ui {

ElidingLabel::ElidingLabel(QWidget* parent) : QLabel(parent) {
    setWordWrap(false);
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
}

void ElidingLabel::setFullText(const QString& text) {
    full_ = text;
    setToolTip(text);
    elide();
}

QSize ElidingLabel::minimumSizeHint() const {
    const int margins = width() - contentsRect().width();  // padding and frame, px
    return {margins + fontMetrics().horizontalAdvance(QStringLiteral("…")),
            QLabel::minimumSizeHint().height()};
}

void ElidingLabel::resizeEvent(QResizeEvent* e) {
    QLabel::resizeEvent(e);
    elide();
}

void ElidingLabel::changeEvent(QEvent* e) {
    QLabel::changeEvent(e);
    if (e->type() == QEvent::FontChange || e->type() == QEvent::StyleChange) elide();
}

void ElidingLabel::elide() {
    const QString shown =
        fontMetrics().elidedText(full_, Qt::ElideRight, std::max(0, contentsRect().width()));
    if (shown != text()) QLabel::setText(shown);
}

}  // namespace trilho::ui
