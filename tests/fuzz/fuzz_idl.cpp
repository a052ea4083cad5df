// SPDX-License-Identifier: MIT
// The IDL preprocessor and parser, then the model queries the Builder and the code generator make
// of what was read (data types for ports, interfaces with their inherited operations).
//
// The text is named as a file in an empty folder, so quoted includes find nothing beside it; no
// search folders are set.

#include "idlparser.h"

#include <QDir>
#include <QTemporaryDir>

#include <cstdint>

namespace {

const QString &fileName()
{
    static const QTemporaryDir folder;
    static const QString name = QDir(folder.path()).filePath(QStringLiteral("fuzz.idl"));
    return name;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QString text = QString::fromUtf8(reinterpret_cast<const char *>(data), qsizetype(size));
    Codegen::IdlParser parser;
    parser.parseText(text, fileName());
    const Codegen::IdlModel &model = parser.model();
    model.dataTypes();
    for (const Codegen::IdlInterface &interface : model.definedInterfaces()) {
        model.allOperations(interface.scopedName);
        model.allAttributes(interface.scopedName);
    }
    return 0;
}
