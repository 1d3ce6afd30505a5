#include "app/cli/program_json.h"

#include <QJsonArray>

#include "core/diagnostic_text.h"

namespace trilho::cli {

QJsonObject programToJson(const QString& file, const Program& program) {
    QJsonArray diagnostics;
    for (const Diagnostic& d : program.diagnostics) {
        QJsonObject o;
        o[QStringLiteral("severity")] =
            d.severity == Severity::Error ? QStringLiteral("error") : QStringLiteral("warning");
        o[QStringLiteral("code")] =
            QString::fromLatin1(d.code().data(), static_cast<qsizetype>(d.code().size()));
        o[QStringLiteral("line")] = static_cast<qint64>(d.line);
        o[QStringLiteral("column")] =
            d.column ? QJsonValue(static_cast<qint64>(d.column)) : QJsonValue(QJsonValue::Null);
        o[QStringLiteral("n")] = d.n >= 0 ? QJsonValue(d.n) : QJsonValue(QJsonValue::Null);
        o[QStringLiteral("message")] = diagnosticMessage(d);
        diagnostics.append(o);
    }
    QJsonArray blocks;
    const bool hasY = !program.y.empty();
    for (std::size_t i = 0; i < program.blocks.size(); ++i) {
        const Block& b = program.blocks[i];
        QJsonObject o;
        o[QStringLiteral("line")] = static_cast<qint64>(b.line);
        o[QStringLiteral("n")] = b.n >= 0 ? QJsonValue(b.n) : QJsonValue(QJsonValue::Null);
        o[QStringLiteral("op")] =
            QString::fromLatin1(opName(b.op).data(), static_cast<qsizetype>(opName(b.op).size()));
        switch (b.op) {
            case Op::Rapid:
            case Op::Linear:
                o[QStringLiteral("x")] = b.x;
                if (hasY) o[QStringLiteral("y")] = program.y[i];
                o[QStringLiteral("feed")] = b.feed;
                break;
            case Op::Feed:
                o[QStringLiteral("feed")] = b.feed;
                break;
            case Op::Dwell:
                o[QStringLiteral("seconds")] = b.seconds();
                break;
            case Op::SetZero:
                o[QStringLiteral("zero")] = b.zero();
                break;
            case Op::Goto:
                o[QStringLiteral("target_n")] = b.targetN();
                o[QStringLiteral("target_index")] = b.targetIndex;
                break;
            default:
                break;
        }
        blocks.append(o);
    }
    QJsonObject root;
    root[QStringLiteral("file")] = file;
    root[QStringLiteral("dialect")] = QString::fromLatin1(dialectName(program.dialect).data());
    root[QStringLiteral("ok")] = program.ok();
    root[QStringLiteral("diagnostics")] = diagnostics;
    root[QStringLiteral("blocks")] = blocks;
    return root;
}

}  // namespace trilho::cli
