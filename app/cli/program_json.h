#pragma once
// The --json shape of `trilho-cli compile` (issue 2), one object per compiled file.
#include <QJsonObject>
#include <QString>

#include "core/program.h"

namespace trilho::cli {

QJsonObject programToJson(const QString& file, const Program& program);

}  // namespace trilho::cli
