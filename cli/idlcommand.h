// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace Cli {

/**
 * `rtctl idl --lang python [-I DIR]... [-o OUTDIR] FILE.idl...`: compiles IDL files to Python
 * modules in omniORBpy's layout (Codegen::PythonStubWriter), for RT Studio's Python runtime, as
 * `omniidl -bpython` does for omniORBpy. OpenRTM's IDL is always on the include path.
 */
class IdlCommand : public Command
{
public:
    QString name() const override { return QStringLiteral("idl"); }
    QString summary() const override;
    QString usage() const override;
    int run(const QStringList &arguments, Streams streams) override;
};

} // namespace Cli
