// SPDX-License-Identifier: MIT
#include "command.h"

namespace Cli {

int Command::usageError(const QString &message, Streams streams) const
{
    streams.err << "rtctl " << name() << ": " << message << "\n\n" << usage();
    streams.err.flush();
    return ExitUsage;
}

} // namespace Cli
