// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "projectwriter.h"

#include <QMetaType>

namespace Builder {

/**
 * What one Generate (or Build) ended with, for whoever shows it (the application's Problems panel and
 * status bar): a one-line summary and one diagnostic per finding. Errors and warnings name the
 * file and line where known (IDL parse errors, the element a rule refuses); on success every
 * written, merged, kept or backed-up file is an Info row naming the file. A Build's rows are the
 * compiler's and CMake's errors and warnings with file, line and column.
 */
struct GenerateOutcome
{
    bool succeeded = false;
    QString summary; ///< one line, e.g. "Generated 12 files into /x/Counter."
    Profile::Diagnostics diagnostics;

    /// Generate wrote into `folder`; `report` lists the files by relative path.
    static GenerateOutcome fromReport(const QString &folder, const Codegen::WriteReport &report);
    /// Generate was refused before anything was written, for these problems.
    static GenerateOutcome refused(const Profile::Diagnostics &problems);
    /// Generate (or Code restore / Clear backups) failed with these problems.
    static GenerateOutcome failed(const Profile::Diagnostics &problems);

    /// True when a diagnostic is an error or a warning (worth showing the panel for).
    bool needsAttention() const;
};

} // namespace Builder

Q_DECLARE_METATYPE(Builder::GenerateOutcome)
