#pragma once
// Syntax colours for both dialects: block numbers, g and m words, axis words, feed, comments.
#include <QRegularExpression>
#include <QSyntaxHighlighter>

namespace trilho {
namespace ui {

class GcodeHighlighter : public QSyntaxHighlighter {
    Q_OBJECT
  public:
    explicit GcodeHighlighter(QTextDocument* document);

  protected:
    void highlightBlock(const QString& text) override;

  private:
    struct Rule {
        QRegularExpression pattern;
        QTextCharFormat format;
    };
    QList<Rule> rules_;
};

}  // namespace ui
}  // namespace trilho
