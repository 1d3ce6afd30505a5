#include "ui/keys_dialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QKeySequence>
#include <QTableWidget>
#include <QVBoxLayout>

namespace trilho {
namespace ui {

QList<std::pair<QString, QString>> KeysDialog::fixedKeys(Machine machine) {
    const auto key = [](Qt::Key k) { return QKeySequence(k).toString(QKeySequence::NativeText); };
    QList<std::pair<QString, QString>> keys{
        {key(Qt::Key_Pause) + QStringLiteral(", ") + key(Qt::Key_F1),
         tr("EMERGENCY STOP, in every window, menu and dialog")},
        {key(Qt::Key_Escape),
         tr("Stop (a controlled stop) when no menu, list or dialog is open; otherwise it only "
            "closes it")},
        {key(Qt::Key_Space), tr("STOP: the manual PARA, or Stop in automatic (not in the editor)")},
    };
    if (machine == Machine::Rail)
        keys << std::pair{QStringLiteral("<  ,"), tr("Manual mode: left")}
             << std::pair{QStringLiteral(">  ."), tr("Manual mode: right")};
    return keys;
}

KeysDialog::KeysDialog(const QList<QAction*>& actions, QWidget* parent, Machine machine)
    : QDialog(parent) {
    setObjectName(QStringLiteral("keysDialog"));
    setWindowTitle(tr("Keys"));
    table_ = new QTableWidget(0, 2, this);
    table_->setHorizontalHeaderLabels({tr("Key"), tr("Action")});
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setWordWrap(true);
    auto add = [this](const QString& key, const QString& what) {
        const int row = table_->rowCount();
        table_->insertRow(row);
        table_->setItem(row, 0, new QTableWidgetItem(key));
        table_->setItem(row, 1, new QTableWidgetItem(what));
    };
    for (const auto& [key, what] : fixedKeys(machine))
        add(key, what);
    for (QAction* a : actions)
        if (!a->shortcut().isEmpty())
            add(a->shortcut().toString(QKeySequence::NativeText),
                QString(a->text()).remove(QLatin1Char('&')));
    table_->resizeColumnsToContents();
    table_->resizeRowsToContents();
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* v = new QVBoxLayout(this);
    v->addWidget(table_);
    v->addWidget(buttons);
    resize(640, 420);
}

}  // namespace ui
}  // namespace trilho
