// trilho-cli calibrate --machine P --port DEV [--axis x|y] [--travel-mm MM]
//                      [--write-profile OUT.json] [--json]: the DC table's calibration on the
// host (issue 22 item 8; seed 004, annex 7, "Programa para pruebas a lazo abierto"). The board
// runs its open-loop program (trilho-device table --calibration) and sends its count every
// 32 ms until 1300 pulses; this command receives the counts (hal/serial), computes pulses
// against time and, given the travel the operator measured, mm per pulse and mm per turn
// (core/xy/dc_calibration.h), and can write them into a copy of the profile. A stream
// the program cannot have sent is refused as it comes or once ended (exit 3, the reason,
// nothing written; issue 30 item 2, core/xy/dc_calibration_check.h).
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>
#include <cmath>
#include <numbers>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "core/files/atomic_file.h"
#include "core/files/replace_target.h"
#include "core/profile/machine_profile.h"
#include "core/xy/dc_calibration.h"
#include "hal/serial/serial_line.h"
#include "host/common/data_paths.h"

namespace trilho::cli {

namespace {
constexpr const char* kCommand = "calibrate";

/// The profile file with dcTable.<axis>.mmPerTurn replaced (every other key, its sources and
/// comments kept); empty and a reason when it cannot.
QByteArray profileWithMmPerTurn(const QString& path, const QString& axis, double mmPerTurn,
                                const QString& note, QString* error) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot read profile %1: %2").arg(path, f.errorString());
        return {};
    }
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(f.readAll(), &pe);
    if (!doc.isObject()) {
        *error = QStringLiteral("profile %1 is not a JSON object: %2").arg(path, pe.errorString());
        return {};
    }
    QJsonObject root = doc.object();
    QJsonObject table = root.value(QStringLiteral("dcTable")).toObject();
    QJsonObject a = table.value(axis).toObject();
    a.insert(QStringLiteral("mmPerTurn"), std::round(mmPerTurn * 1e5) / 1e5);
    const QString source = a.value(QStringLiteral("source")).toString();
    a.insert(QStringLiteral("source"),
             source.isEmpty() ? note : source + QStringLiteral("; ") + note);
    table.insert(axis, a);
    root.insert(QStringLiteral("dcTable"), table);
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}
}  // namespace

int calibrateCommand(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Calibrate an axis of the DC XY table (seed 004's open-loop program): receive the "
        "board's encoder counts, compute pulses against time and, with the travel measured, "
        "the axis' millimetres per pulse and per turn. A stream the program cannot have sent "
        "(a stall, garbage, counts above 1300, a flood, a gap, a board that stops early) is "
        "refused: exit 3 with the reason, nothing written."));
    const QCommandLineOption machineOpt(QStringLiteral("machine"),
                                        QStringLiteral("The table's profile (xy-dc-table)."),
                                        QStringLiteral("PROFILE"));
    const QCommandLineOption portOpt(
        QStringLiteral("port"), QStringLiteral("Serial port of the board."), QStringLiteral("DEV"));
    const QCommandLineOption baudOpt(QStringLiteral("baud"),
                                     QStringLiteral("Bit rate (default 9600)."),
                                     QStringLiteral("N"), QStringLiteral("9600"));
    const QCommandLineOption axisOpt(
        QStringLiteral("axis"), QStringLiteral("The axis the program drives: x (default) or y."),
        QStringLiteral("AXIS"), QStringLiteral("x"));
    const QCommandLineOption travelOpt(
        QStringLiteral("travel-mm"),
        QStringLiteral("The travel measured from where the axis started to where it stopped, mm "
                       "(without it: pulses against time only)."),
        QStringLiteral("MM"));
    const QCommandLineOption timeoutOpt(
        QStringLiteral("timeout"),
        QStringLiteral("Seconds to wait for the stream (default 600: the seed's program raises "
                       "its PWM 0.4 % every 64 ms until the axis moves)."),
        QStringLiteral("S"), QStringLiteral("600"));
    const QCommandLineOption quietOpt(
        QStringLiteral("quiet-seconds"),
        QStringLiteral("The stream has ended after this silence once counts came (default 1)."),
        QStringLiteral("S"), QStringLiteral("1"));
    const QCommandLineOption writeOpt(
        QStringLiteral("write-profile"),
        QStringLiteral("Write the profile with the axis' mmPerTurn measured to OUT (atomically; "
                       "needs --travel-mm)."),
        QStringLiteral("OUT"));
    const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                     QStringLiteral("Print the result as JSON, with every count."));
    parser.addOptions({machineOpt, portOpt, baudOpt, axisOpt, travelOpt, timeoutOpt, quietOpt,
                       writeOpt, jsonOpt});
    if (auto done = parseArguments(parser, args, kCommand)) return *done;
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            kCommand,
            QStringLiteral("no FILE is taken (got %1)").arg(parser.positionalArguments().front()));
    if (!parser.isSet(machineOpt)) return usageError(kCommand, QStringLiteral("give --machine"));
    if (!parser.isSet(portOpt)) return usageError(kCommand, QStringLiteral("give --port"));
    const QString axis = parser.value(axisOpt);
    if (axis != QLatin1String("x") && axis != QLatin1String("y"))
        return usageError(kCommand, QStringLiteral("--axis: must be x or y (got %1)").arg(axis));
    auto number = [&](const QCommandLineOption& o, double lo, double hi, double& into) {
        bool ok = false;
        const double v = parser.value(o).toDouble(&ok);
        if (!ok || !(v >= lo && v <= hi)) {
            usageError(kCommand, QStringLiteral("--%1: must be a number from %2 to %3 (got %4)")
                                     .arg(o.names().front())
                                     .arg(lo)
                                     .arg(hi)
                                     .arg(parser.value(o)));
            return false;
        }
        into = v;
        return true;
    };
    double baud = 9600, timeoutS = 600, quietS = 1, travel = 0;
    if (!number(baudOpt, 50, 4000000, baud) || !number(timeoutOpt, 0.1, 86400, timeoutS) ||
        !number(quietOpt, 0.05, 60, quietS))
        return kUsage;
    if (parser.isSet(travelOpt) && !number(travelOpt, 0.001, 100000, travel)) return kUsage;
    if (parser.isSet(writeOpt) && !parser.isSet(travelOpt))
        return usageError(kCommand, QStringLiteral("--write-profile needs --travel-mm: the mm per "
                                                   "pulse comes from the travel measured"));
    if (parser.isSet(writeOpt)) {
        if (const QString refused = refuseToReplace(parser.value(writeOpt)); !refused.isEmpty())
            return usageError(kCommand, QStringLiteral("--write-profile: %1").arg(refused));
    }
    const QString profilePath = machineProfilePath(parser.value(machineOpt));
    const ProfileLoad load = loadMachineProfile(profilePath);
    if (!load.profile) return usageError(kCommand, load.error);
    if (load.profile->kind != MachineKind::DcTable)
        return usageError(kCommand, QStringLiteral("%1 is not an xy-dc-table profile: only the DC "
                                                   "table has this calibration")
                                        .arg(profilePath));
    const DcAxisParams& params =
        axis == QLatin1String("x") ? load.profile->dcTable.x : load.profile->dcTable.y;

    SerialLine line;
    QString error;
    if (!line.open({parser.value(portOpt), static_cast<int>(baud), false}, &error))
        return usageError(kCommand, error);
    // The stream is checked as it comes (core/xy/dc_calibration_check.h): a stream the
    // program cannot have sent ends the wait at once, and memory stays bounded whatever the
    // board sends.
    CalibrationRecorder recorder(CalibrationLimits::forAxis(params));
    QElapsedTimer clock;
    clock.start();
    auto now = [&] { return static_cast<double>(clock.nsecsElapsed()) * 1e-9; };
    QString lostWhy;
    bool timedOut = false;
    QObject::connect(&line, &SerialLine::received, [&](const QByteArray& bytes) {
        const double t = now();
        for (char b : bytes) {
            recorder.receive(static_cast<std::uint8_t>(b), t);
            if (!recorder.refused().empty()) break;
        }
        if (!recorder.refused().empty()) QCoreApplication::quit();
    });
    QObject::connect(&line, &SerialLine::lost, [&](const QString& why) {
        lostWhy = why;
        QCoreApplication::quit();
    });
    QTimer check;
    QObject::connect(&check, &QTimer::timeout, [&] {
        const double t = now();
        const bool ended = !recorder.samples().empty() && t - recorder.lastByteS() > quietS;
        timedOut = !ended && t > timeoutS;
        if (ended || timedOut) QCoreApplication::quit();
    });
    check.start(20);
    QCoreApplication::exec();
    check.stop();
    line.close();
    const QString place =
        QStringLiteral("trilho-cli calibrate: axis %1 on %2: ").arg(axis, parser.value(portOpt));
    const QString nothingWritten =
        parser.isSet(writeOpt)
            ? QStringLiteral("; nothing written to %1").arg(parser.value(writeOpt))
            : QString();
    if (!lostWhy.isEmpty() && recorder.samples().empty() && recorder.refused().empty()) {
        err(QStringLiteral("trilho-cli calibrate: %1%2\n").arg(lostWhy, nothingWritten));
        return kAlarm;
    }
    // A stream that did not end by the board's silence is no run: the line lost under it, or
    // still coming at --timeout (a board that never stops).
    QString unended;
    if (recorder.refused().empty() && !recorder.samples().empty()) {
        const CalibrationSample& last = recorder.samples().back();
        if (!lostWhy.isEmpty())
            unended = QStringLiteral(
                          "%1 after %2 counts (the last %3 at %4 s): the stream is not "
                          "known to have ended")
                          .arg(lostWhy)
                          .arg(recorder.samples().size())
                          .arg(last.count)
                          .arg(last.tS, 0, 'f', 3);
        else if (timedOut)
            unended = QStringLiteral(
                          "the board was still sending at --timeout (%1 s), at count "
                          "%2: the stream did not end")
                          .arg(timeoutS)
                          .arg(last.count);
    }
    if (!unended.isEmpty()) {
        err(place + unended + nothingWritten + QStringLiteral("\n"));
        return kAlarm;
    }

    CalibrationInput in = recorder.input();
    in.radPerCount = params.radPerCount;
    if (parser.isSet(travelOpt)) in.travelMm = travel;
    const CalibrationResult r = calibrate(in);
    if (!r.ok) {
        err(place + QString::fromStdString(r.error) +
            (in.samples.empty() && in.refused.empty()
                 ? QStringLiteral(" (waited %1 s)").arg(timeoutS)
                 : QString()) +
            nothingWritten + QStringLiteral("\n"));
        return kAlarm;
    }

    if (parser.isSet(writeOpt)) {
        const QString note =
            QStringLiteral("mmPerTurn measured by trilho-cli calibrate: %1 pulses over %2 mm")
                .arg(r.pulsesAtStop, 0, 'f', 1)
                .arg(travel);
        const QByteArray bytes =
            profileWithMmPerTurn(profilePath, axis, *r.mmPerTurn, note, &error);
        if (bytes.isEmpty()) return usageError(kCommand, error);
        // Check what is written: a profile trilho reads back.
        const ProfileLoad again = machineProfileFromJson(bytes, parser.value(writeOpt));
        if (!again.profile) return usageError(kCommand, again.error);
        if (const QString refused = refuseToReplace(parser.value(writeOpt)); !refused.isEmpty())
            return usageError(kCommand, QStringLiteral("--write-profile: %1").arg(refused));
        if (QString why; !saveFileAtomically(parser.value(writeOpt), bytes, &why))
            return usageError(kCommand, QStringLiteral("cannot write profile: %1").arg(why));
    }

    const double oldMmPerPulse = params.mmPerTurn * params.radPerCount / (2.0 * std::numbers::pi);
    const double mmPerPulse = r.mmPerPulse ? *r.mmPerPulse : oldMmPerPulse;
    if (parser.isSet(jsonOpt)) {
        QJsonObject o;
        o[QStringLiteral("axis")] = axis;
        o[QStringLiteral("counts")] = static_cast<qint64>(r.samples);
        o[QStringLiteral("dropped")] = static_cast<qint64>(recorder.dropped());
        o[QStringLiteral("firstPulseS")] = r.firstPulseS;
        o[QStringLiteral("lastCount")] = r.lastCount;
        o[QStringLiteral("lastS")] = r.lastS;
        o[QStringLiteral("pulsesPerS")] = r.pulsesPerS;
        o[QStringLiteral("pulsesAtStop")] = r.pulsesAtStop;
        o[QStringLiteral("profileMmPerTurn")] = params.mmPerTurn;
        if (r.mmPerTurn) {
            o[QStringLiteral("travelMm")] = travel;
            o[QStringLiteral("mmPerPulse")] = *r.mmPerPulse;
            o[QStringLiteral("mmPerTurn")] = *r.mmPerTurn;
            o[QStringLiteral("speedMmS")] = *r.speedMmS;
        }
        if (parser.isSet(writeOpt)) o[QStringLiteral("written")] = parser.value(writeOpt);
        // Pulses against time and displacement (mm per pulse measured, or the profile's).
        QJsonArray samples;
        for (const CalibrationSample& s : in.samples)
            samples.append(QJsonArray{s.tS, s.count, s.count * mmPerPulse});
        o[QStringLiteral("samples")] = samples;
        o[QStringLiteral("samplesColumns")] = QJsonArray{
            QStringLiteral("tS"), QStringLiteral("count"), QStringLiteral("displacementMm")};
        out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Indented)));
        return kOk;
    }
    QString text = QStringLiteral(
                       "axis %1: %2 counts, first pulse at %3 s, last count %4 at %5 s\n"
                       "pulses against time: %6 pulses/s; the board stopped at about %7 "
                       "pulses\n")
                       .arg(axis)
                       .arg(r.samples)
                       .arg(r.firstPulseS, 0, 'f', 3)
                       .arg(r.lastCount)
                       .arg(r.lastS, 0, 'f', 3)
                       .arg(r.pulsesPerS, 0, 'f', 1)
                       .arg(r.pulsesAtStop, 0, 'f', 1);
    if (r.mmPerTurn) {
        text += QStringLiteral(
                    "travel %1 mm: %2 mm per pulse, %3 mm per turn (the profile has "
                    "%4), %5 mm/s\n")
                    .arg(travel)
                    .arg(*r.mmPerPulse, 0, 'f', 5)
                    .arg(*r.mmPerTurn, 0, 'f', 4)
                    .arg(params.mmPerTurn)
                    .arg(*r.speedMmS, 0, 'f', 1);
    } else {
        text += QStringLiteral(
                    "give --travel-mm (the travel measured) for mm per pulse; at the "
                    "profile's %1 mm per turn the axis ran about %2 mm\n")
                    .arg(params.mmPerTurn)
                    .arg(r.pulsesAtStop * oldMmPerPulse, 0, 'f', 1);
    }
    if (parser.isSet(writeOpt)) text += QStringLiteral("written: %1\n").arg(parser.value(writeOpt));
    out(text);
    return kOk;
}

}  // namespace trilho::cli
