#pragma once
// Polygons from points (seed 001 3.1.4: its Java host built its test objects "por meio de
// pontos"): the operator types the vertices, one "x y" in mm a line; the dialog closes the
// polygon back to the first point and makes a program of it, a g00 to the first vertex and a
// g01 to each next one at the chosen feed, which the plotter window then runs (issue 22 item
// 12).
#include <QDialog>
#include <QPointF>
#include <vector>

class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;

namespace trilho {
namespace ui {

struct PolygonPoints {
    std::vector<QPointF> points;  ///< mm
    QString error;                ///< empty when the text is a polygon
};

/// Reads "x y" (or "x, y" / "x; y") a line, mm; blank lines are skipped. At least three
/// points; a bad line is named: "line 3: expected two numbers, x and y (got 'abc')".
PolygonPoints parsePolygonPoints(const QString& text);
/// The closed polygon as a standard-dialect program: G90, G00 to the first point, G01 F to
/// each next one and back to the first, M02.
QString polygonProgram(const std::vector<QPointF>& points, double feedPercent);

class PolygonDialog : public QDialog {
    Q_OBJECT
  public:
    explicit PolygonDialog(QWidget* parent = nullptr);
    /// The program of the points typed (valid once accepted).
    QString program() const;
    QPlainTextEdit* pointsEdit() const { return points_; }
    QDoubleSpinBox* feedBox() const { return feed_; }
    QLabel* errorLabel() const { return error_; }
    QDialogButtonBox* buttons() const { return buttons_; }

  public slots:
    void accept() override;

  private:
    QPlainTextEdit* points_;
    QDoubleSpinBox* feed_;
    QLabel* error_;
    QDialogButtonBox* buttons_;
    QString program_;
};

}  // namespace ui
}  // namespace trilho
