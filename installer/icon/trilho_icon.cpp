// trilho-icon OUTDIR SIZE...: draws trilho's icon (a carriage on a rail between its two end
// switches) as OUTDIR/scalable/apps/trilho.svg and OUTDIR/SIZExSIZE/apps/trilho.png, the
// hicolor theme's layout. One drawing, two outputs: the shapes below are written as SVG and
// painted with QPainter.
#include <QColor>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QPainter>
#include <QString>
#include <cstdio>
#include <vector>

namespace {

struct Shape {
    enum Kind { Rect, Circle } kind;
    double x, y, w, h, radius;  ///< Rect: corner, size, corner radius. Circle: centre, radius.
    const char* fill;
};

// On a 256 x 256 canvas.
const std::vector<Shape> kShapes = {
    {Shape::Rect, 12, 12, 232, 232, 44, "#24405f"},  // tile
    {Shape::Rect, 30, 168, 196, 20, 5, "#c9d1da"},   // the rail
    {Shape::Rect, 30, 188, 196, 8, 3, "#8d99a6"},    // its shadow
    {Shape::Rect, 22, 140, 16, 60, 4, "#e5533d"},    // left end switch
    {Shape::Rect, 218, 140, 16, 60, 4, "#e5533d"},   // right end switch
    {Shape::Rect, 84, 104, 88, 56, 10, "#f2b630"},   // the carriage
    {Shape::Rect, 84, 142, 88, 18, 0, "#d99a17"},    // its lower edge
    {Shape::Rect, 116, 54, 24, 56, 6, "#f2b630"},    // the robot's column
    {Shape::Circle, 128, 54, 0, 0, 22, "#f2b630"},   // its head
    {Shape::Circle, 128, 54, 0, 0, 9, "#24405f"},    // the head's joint
    {Shape::Circle, 104, 168, 0, 0, 14, "#2e3640"},  // wheels
    {Shape::Circle, 152, 168, 0, 0, 14, "#2e3640"}, {Shape::Circle, 104, 168, 0, 0, 5, "#c9d1da"},
    {Shape::Circle, 152, 168, 0, 0, 5, "#c9d1da"},
};

QString svg() {
    QString s = QStringLiteral(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"256\" height=\"256\" "
        "viewBox=\"0 0 256 256\">\n");
    for (const Shape& sh : kShapes) {
        if (sh.kind == Shape::Rect)
            s += QStringLiteral(
                     "  <rect x=\"%1\" y=\"%2\" width=\"%3\" height=\"%4\" rx=\"%5\" "
                     "fill=\"%6\"/>\n")
                     .arg(sh.x)
                     .arg(sh.y)
                     .arg(sh.w)
                     .arg(sh.h)
                     .arg(sh.radius)
                     .arg(QLatin1String(sh.fill));
        else
            s += QStringLiteral("  <circle cx=\"%1\" cy=\"%2\" r=\"%3\" fill=\"%4\"/>\n")
                     .arg(sh.x)
                     .arg(sh.y)
                     .arg(sh.radius)
                     .arg(QLatin1String(sh.fill));
    }
    return s + QStringLiteral("</svg>\n");
}

QImage png(int size) {
    QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    p.scale(size / 256.0, size / 256.0);
    p.setPen(Qt::NoPen);
    for (const Shape& sh : kShapes) {
        p.setBrush(QColor(QLatin1String(sh.fill)));
        if (sh.kind == Shape::Rect)
            p.drawRoundedRect(QRectF(sh.x, sh.y, sh.w, sh.h), sh.radius, sh.radius);
        else
            p.drawEllipse(QPointF(sh.x, sh.y), sh.radius, sh.radius);
    }
    return image;
}

bool write(const QString& path, const QByteArray& bytes) {
    QDir().mkpath(path.section(QLatin1Char('/'), 0, -2));
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

}  // namespace

int main(int argc, char* argv[]) {
    if (argc < 3) {
        std::fputs("usage: trilho-icon OUTDIR SIZE...\n", stderr);
        return 2;
    }
    const QString out = QString::fromLocal8Bit(argv[1]);
    if (!write(out + QStringLiteral("/scalable/apps/trilho.svg"), svg().toUtf8())) {
        std::fprintf(stderr, "trilho-icon: cannot write the SVG in %s\n", argv[1]);
        return 1;
    }
    for (int i = 2; i < argc; ++i) {
        const int size = QString::fromLocal8Bit(argv[i]).toInt();
        const QString dir = out + QStringLiteral("/%1x%1/apps").arg(size);
        QDir().mkpath(dir);
        if (size <= 0 || !png(size).save(dir + QStringLiteral("/trilho.png"))) {
            std::fprintf(stderr, "trilho-icon: cannot write the %s px PNG\n", argv[i]);
            return 1;
        }
    }
    return 0;
}
