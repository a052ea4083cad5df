// SPDX-License-Identifier: MIT
// rtshell paths as rtctl reads them (`/localhost/ctx.kind/Name0.rtc:port`, `..`, `corbaloc::h`).
//
// Input: the path, and after the first newline the current directory it is relative to. A path
// that parses must print as text that parses to the same path.

#include "rtpath.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QString input = QString::fromUtf8(reinterpret_cast<const char *>(data), qsizetype(size));
    const qsizetype newline = input.indexOf(QLatin1Char('\n'));
    const QString text = newline < 0 ? input : input.left(newline);
    const QString currentDirectory = newline < 0 ? QString() : input.mid(newline + 1);
    QString error;
    const std::optional<Corba::RtPath> path = Corba::RtPath::parse(text, currentDirectory, &error);
    if (!path)
        return 0;
    path->nameServiceAddress();
    path->names();
    const std::optional<Corba::RtPath> again = Corba::RtPath::parse(path->toString(), QString(), &error);
    if (!again || *again != *path || again->withoutPort() != path->withoutPort())
        std::abort();
    return 0;
}
