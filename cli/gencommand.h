// SPDX-License-Identifier: MIT
#pragma once

#include "command.h"

namespace Cli {

/**
 * `rtctl gen RTC.xml --lang L… -o DIR [--idl-dir D]… [--merge|--overwrite|--keep]
 * [--templates DIR] [--backups N] [--test-component]`: generates the component project of an RTC
 * Profile, as the RTC Builder's Generate button does; --test-component adds the C++ test
 * component under `test/`. Existing files that differ are kept unless --merge or
 * --overwrite says otherwise; merged and overwritten files are backed up first.
 */
class GenCommand : public Command
{
public:
    QString name() const override { return QStringLiteral("gen"); }
    QString summary() const override;
    QString usage() const override;
    int run(const QStringList &arguments, Streams streams) override;
};

} // namespace Cli
