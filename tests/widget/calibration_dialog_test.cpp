// Issue 22 item 8: the table's calibration dialog receives the board's stream (seed 004,
// annex 7, "Programa para pruebas a lazo abierto": counts LSB then MSB every 32 ms while under
// 1300), plots pulses against time and displacement, and derives mm per turn from the travel.
#include <QApplication>
#include <QtTest>
#include <cmath>
#include <numbers>

#include "tests/support/calibration_streams.h"
#include "tests/support/widget_test_main.h"
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
    // Issue 30 item 2: the dialog believes no stream the program cannot have sent: each bad
    // stream ends with its reason, no result and nothing to save (before: a profile with mm per
    // turn between 0.013 and 0.77 for a true 2.12).
    void badStreamsAreRefused_data() {
        QTest::addColumn<int>("which");
        QTest::addColumn<QString>("why");
        QTest::newRow("stall at 599") << 0 << QStringLiteral("stood at 599");
        QTest::newRow("garbage") << 1 << QStringLiteral("the program cannot have sent");
        QTest::newRow("counts of 60000") << 2 << QStringLiteral("at or above the program's stop");
        QTest::newRow("replug, restart") << 3 << QStringLiteral("went back");
        QTest::newRow("replug, gap") << 4 << QStringLiteral("counts are missing");
        QTest::newRow("dies mid-stream") << 5 << QStringLiteral("ended at count");
    }
    void badStreamsAreRefused() {
        QFETCH(int, which);
        QFETCH(QString, why);
        const test::BoardStream streams[] = {test::stallAt599(),     test::garbage(),
                                             test::counts60000(),    test::restartAfterReplug(),
                                             test::gapAfterReplug(), test::diesMidStream()};
        ui::CalibrationDialog d(MachineProfile::xyDcTable(), QString(), 9600);
        d.setAxis(0);
        const test::BoardStream& s = streams[which];
        for (std::size_t k = 0; k < s.ticks.size(); ++k)
            d.receive(QByteArray(reinterpret_cast<const char*>(s.ticks[k].data()),
                                 static_cast<qsizetype>(s.ticks[k].size())),
                      static_cast<double>(k + 1) * test::kTickS);
        d.setTravelMm(test::goodTravelMm());
        const CalibrationResult r = d.compute();
        QVERIFY2(!r.ok, qPrintable(QStringLiteral("%1: calibrated to %2 mm per turn")
                                       .arg(QString::fromStdString(s.name))
                                       .arg(r.mmPerTurn ? *r.mmPerTurn : 0.0)));
        QVERIFY2(QString::fromStdString(r.error).contains(why), r.error.c_str());
        QVERIFY(!d.calibratedProfile());
    }
    void aFloodEndsAtOnceWithBoundedMemory() {
        // 1 MB of counts that never go back, as fast as a pseudo-terminal carries them.
        ui::CalibrationDialog d(MachineProfile::xyDcTable(), QString(), 9600);
        constexpr int kCap = 16384;  // CalibrationLimits::maxSamples
        QByteArray chunk;
        double t = 1.0;
        int maxPoints = 0;
        for (int n = 0; n < 256; ++n) {
            chunk.clear();
            for (int i = 0; i < 2048; ++i) {
                const auto c = static_cast<std::uint16_t>((n * 2048 + i) / 8192);
                chunk.append(static_cast<char>(c & 0xFF));
                chunk.append(static_cast<char>(c >> 8));
            }
            d.receive(chunk, t);
            t += 4096.0 / 80e6;
            maxPoints = std::max(maxPoints, d.points());
        }
        QVERIFY2(maxPoints <= kCap, qPrintable(QString::number(maxPoints)));
        // Said at once, before Compute; then nothing to compute or save.
        QVERIFY2(d.resultText().contains(QStringLiteral("more bytes than the program sends")),
                 qPrintable(d.resultText()));
        d.setTravelMm(test::goodTravelMm());
        QVERIFY(!d.compute().ok);
        QVERIFY(!d.calibratedProfile());
    }
    void garbageAfterAResultTakesTheResultBack() {
        // The operator computed a good run; then the board sends garbage (it was reset, another
        // program runs): the stream is no longer the program's run, and the result goes.
        ui::CalibrationDialog d(MachineProfile::xyDcTable(), QString(), 9600);
        const test::BoardStream good = test::goodStream();
        std::size_t k = 0;
        for (; k < good.ticks.size(); ++k)
            d.receive(QByteArray(reinterpret_cast<const char*>(good.ticks[k].data()), 2),
                      static_cast<double>(k + 1) * test::kTickS);
        d.setTravelMm(test::goodTravelMm());
        QVERIFY(d.compute().ok);
        QVERIFY(d.calibratedProfile());
        const test::BoardStream junk = test::garbage(8);
        for (const std::vector<std::uint8_t>& tick : junk.ticks)
            d.receive(QByteArray(reinterpret_cast<const char*>(tick.data()), 2),
                      static_cast<double>(++k + 40) * test::kTickS);
        QVERIFY(!d.calibratedProfile());
        QVERIFY2(d.resultText().contains(QStringLiteral("refused")), qPrintable(d.resultText()));
        QVERIFY(!d.compute().ok);
    }
    void aPortThatIsNotThereIsNamed() {
        ui::CalibrationDialog d(MachineProfile::xyDcTable(), QStringLiteral("/nonexistent/tty"),
                                9600);
        const CalibrationResult r = d.compute();  // nothing came
        QVERIFY(!r.ok);
        QVERIFY(QString::fromStdString(r.error).contains(QStringLiteral("no count came")));
    }
};

TRILHO_WIDGET_TEST_MAIN(CalibrationDialogTest)
#include "calibration_dialog_test.moc"
