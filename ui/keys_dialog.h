#pragma once
// Help > Keys: every key the screens answer, built from the actions themselves so the page can
// never list a key that does nothing (or miss one that does).
#include <QDialog>
#include <QList>

class QAction;
class QTableWidget;

namespace trilho {
namespace ui {

class KeysDialog : public QDialog {
    Q_OBJECT
  public:
    /// Whose screen: the rail's manual mode also answers < and > (the XY machines jog with
    /// their panel's buttons).
    enum class Machine { Rail, Xy };
    explicit KeysDialog(const QList<QAction*>& actions, QWidget* parent = nullptr,
                        Machine machine = Machine::Rail);
    QTableWidget* table() const { return table_; }
    /// The keys handled outside actions (E-stop, Esc, Space, < >), as "key", "what it does".
    static QList<std::pair<QString, QString>> fixedKeys(Machine machine = Machine::Rail);

  private:
    QTableWidget* table_;
};

}  // namespace ui
}  // namespace trilho
