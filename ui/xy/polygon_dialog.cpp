#include "ui/xy/polygon_dialog.h"

#include <cmath>

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace trilho {
namespace ui {

PolygonPoints parsePolygonPoints(const QString& text) {
    PolygonPoints r;
    const QStringList lines = text.split(QLatin1Char('\n'));
    static const QRegularExpression separators(QStringLiteral("[\\s,;]+"));
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString line = lines[i].trimmed();
        if (line.isEmpty()) continue;
        const QStringList parts = line.split(separators, Qt::SkipEmptyParts);
        bool okX = false, okY = false;
        const double x = parts.size() == 2 ? parts[0].toDouble(&okX) : 0.0;
        const double y = parts.size() == 2 ? parts[1].toDouble(&okY) : 0.0;
        if (!okX || !okY || !std::isfinite(x) || !std::isfinite(y)) {
            r.error = PolygonDialog::tr("line %1: expected two numbers, x and y in mm (got '%2')")
                          .arg(i + 1)
                          .arg(line.left(40));
            r.points.clear();
            return r;
        }
        r.points.emplace_back(x, y);
    }
    if (r.points.size() < 3)
        r.error = PolygonDialog::tr("a polygon needs at least three points (got %1)")
                      .arg(r.points.size());
    return r;
}

QString polygonProgram(const std::vector<QPointF>& points, double feedPercent) {
    auto mm = [](double v) { return QString::number(v, 'f', 3); };
    QString g = QStringLiteral("; Polygon of %1 points (seed 001 3.1.4)\nG90\n").arg(points.size());
    if (points.empty()) return g + QStringLiteral("M02\n");
    g += QStringLiteral("G00 X%1 Y%2\n").arg(mm(points[0].x()), mm(points[0].y()));
    for (std::size_t i = 1; i <= points.size(); ++i) {
        const QPointF& p = points[i % points.size()];  // back to the first: closed
        g += QStringLiteral("G01 X%1 Y%2").arg(mm(p.x()), mm(p.y()));
        if (i == 1) g += QStringLiteral(" F%1").arg(QString::number(feedPercent, 'f', 1));
        g += QLatin1Char('\n');
    }
    return g + QStringLiteral("M02\n");
}

PolygonDialog::PolygonDialog(QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Polygon from points"));
    points_ = new QPlainTextEdit(this);
    points_->setObjectName(QStringLiteral("polygonPoints"));
    points_->setPlaceholderText(tr("One point a line: x y in mm (e.g. 20 20)"));
    feed_ = new QDoubleSpinBox(this);
    feed_->setObjectName(QStringLiteral("polygonFeed"));
    feed_->setRange(1.0, 100.0);
    feed_->setDecimals(0);
    feed_->setSuffix(QStringLiteral(" %"));
    feed_->setValue(45.0);  // the profile's 450 of 1000 steps/s (figure 48)
    error_ = new QLabel(this);
    error_->setObjectName(QStringLiteral("polygonError"));
    error_->setStyleSheet(QStringLiteral("color: rgb(170,0,0);"));
    error_->setWordWrap(true);
    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons_->button(QDialogButtonBox::Ok)->setText(tr("Plot"));
    auto* form = new QFormLayout;
    form->addRow(tr("Vertices (x y, mm):"), points_);
    form->addRow(tr("Feed:"), feed_);
    auto* v = new QVBoxLayout(this);
    v->addLayout(form);
    v->addWidget(new QLabel(tr("The polygon is closed back to its first point."), this));
    v->addWidget(error_);
    v->addWidget(buttons_);
    connect(buttons_, &QDialogButtonBox::accepted, this, &PolygonDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

QString PolygonDialog::program() const {
    return program_;
}

void PolygonDialog::accept() {
    const PolygonPoints p = parsePolygonPoints(points_->toPlainText());
    if (!p.error.isEmpty()) {
        error_->setText(p.error);
        return;  // stays open: the operator corrects the line named
    }
    error_->clear();
    program_ = polygonProgram(p.points, feed_->value());
    QDialog::accept();
}

}  // namespace ui
}  // namespace trilho
