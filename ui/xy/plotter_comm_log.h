#pragma once
// The communication log of seed 001's Java host (figure 48): each packet sent and the byte that
// answered it, with the time, the objects marked, each object's total time after its DONE, and
// a button that clears the log (issue 22 item 12). Bytes are printed signed, as Java's byte
// printed them in the figure ([109, 2, -124, 1, 58, 46]).
#include <QWidget>

#include "core/protocol/plotter_log.h"

class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace trilho {
namespace ui {

class PlotterCommLog : public QWidget {
    Q_OBJECT
  public:
    explicit PlotterCommLog(QWidget* parent = nullptr);

    /// Adds one packet or answer (the plotter link's monitor calls it on the GUI thread).
    void addEntry(const PlotterLogEntry& e);
    /// Forgets every line (the seed's "Limpar Log").
    void clear();
    /// The log's text; lines is its line count.
    QString text() const;
    int lines() const;
    QPushButton* clearButton() const { return clear_; }
    QLabel* lastObjectLabel() const { return lastObject_; }
    /// Lines kept; older ones are dropped (a long drawing sends thousands of packets).
    static constexpr int kMaxLines = 5000;

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();

    QPlainTextEdit* view_;
    QPushButton* clear_;
    QLabel* lastObject_;
    QString pendingSent_;  ///< the line of a packet sent, waiting for its answer
    double lastObjectS_ = -1.0;
};

/// "MOVE [109, 2, -124, 1, 58, 46]" (signed bytes, as figure 48).
QString packetText(const plotter_wire::Packet& p);
/// "NEXT [110]": the answer's name given the command in flight (RESEND shares 114 with
/// REQUEST; a jog echoes its own byte).
QString answerText(std::uint8_t answer, std::uint8_t commandInFlight);

}  // namespace ui
}  // namespace trilho
