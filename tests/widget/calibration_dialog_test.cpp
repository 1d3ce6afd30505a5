// Issue 22 item 8: the table's calibration dialog receives the board's stream (seed 004,
// annex 7, "Programa para pruebas a lazo abierto": counts LSB then MSB every 32 ms while under
// 1300), plots pulses against time and displacement, and derives mm per turn from the travel.
#include <QApplication>
#include <QtTest>
#include <cmath>
#include <numbers>

#include "ui/xy/calibration_dialog.h"

using namespace trilho;

class CalibrationDialogTest : public QObject {
    Q_OBJECT
  private slots:
    void streamToMmPerTurn() {
        MachineProfile profile = MachineProfile::xyDcTable();
        profile.dcTable.x.mmPerTurn = 2.0;  // the guess before calibrating
        ui::CalibrationDialog d(profile, QString(), 9600);
        d.setAxis(0);
        // 700 pulses/s from 0.1 s, one count every 32 ms while under 1300.
        int sent = 0;
        double last = 0;
        for (int k = 1;; ++k) {
            const double t = 0.032 * k;
            const auto c = static_cast<std::uint16_t>(std::max(0.0, std::floor(700.0 * (t - 0.1))));
            if (c >= 1300) break;
            QByteArray pair;
            pair.append(static_cast<char>(c & 0xFF));
            pair.append(static_cast<char>(c >> 8));
            d.receive(pair, t);
            ++sent;
            last = c;
        }
        QCOMPARE(d.points(), sent);
        QVERIFY(!d.calibratedProfile());  // no travel yet
        const double stopAt = std::max(1300.0, last + 700.0 * 0.032);
        d.setTravelMm(stopAt * 2.12 * 0.314 / (2.0 * std::numbers::pi));
        const CalibrationResult r = d.compute();
        QVERIFY(r.ok);
        QVERIFY(r.mmPerTurn);
        QVERIFY(std::abs(*r.mmPerTurn - 2.12) < 0.005);
        const std::optional<MachineProfile> p = d.calibratedProfile();
        QVERIFY(p);
        QVERIFY(std::abs(p->dcTable.x.mmPerTurn - 2.12) < 0.005);
        QCOMPARE(p->dcTable.y.mmPerTurn, 2.0);
    }
    void aPortThatIsNotThereIsNamed() {
        ui::CalibrationDialog d(MachineProfile::xyDcTable(), QStringLiteral("/nonexistent/tty"),
                                9600);
        const CalibrationResult r = d.compute();  // nothing came
        QVERIFY(!r.ok);
        QVERIFY(QString::fromStdString(r.error).contains(QStringLiteral("no count came")));
    }
};

QTEST_MAIN(CalibrationDialogTest)
#include "calibration_dialog_test.moc"
