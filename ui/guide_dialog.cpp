#include "ui/guide_dialog.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

#include "host/common/data_paths.h"

namespace trilho::ui {

GuideDialog::GuideDialog(const QString& fileName, const QString& title, QWidget* parent)
    : QDialog(parent), browser_(new QTextBrowser(this)) {
    setWindowTitle(title);
    setAttribute(Qt::WA_DeleteOnClose);
    browser_->setOpenExternalLinks(true);
    const QString path = QDir(docsDir()).filePath(fileName);
    if (QFileInfo(path).isReadable()) {
        // As a Markdown resource: its relative links and screenshots resolve beside it.
        browser_->setSource(QUrl::fromLocalFile(path), QTextDocument::MarkdownResource);
        loaded_ = !browser_->toPlainText().isEmpty();
    }
    if (!loaded_)
        browser_->setPlainText(tr("The guide is not installed here: %1 cannot be read.")
                                   .arg(QDir::toNativeSeparators(path)));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(browser_);
    layout->addWidget(buttons);
    // Room for a page of text, never more than a 1024x768 screen.
    resize(760, 640);
}

}  // namespace trilho::ui
