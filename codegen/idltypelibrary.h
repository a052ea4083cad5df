// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "idlmodel.h"

#include <QStringList>

#include <functional>

namespace Codegen {

/// The IDL types the RTC Builder offers: every `.idl` file directly in a set of folders (the OpenRTM
/// IDL set, the project's idl/, user folders) parsed into one model. The folders are also the include
/// search path. Files are read in folder order, then by name, so results do not depend on the disk. A
/// file name seen before (directly or through an include) is not read again from a later folder.
class IdlTypeLibrary
{
public:
    explicit IdlTypeLibrary(const QStringList &directories = {});

    /// Told before each file is parsed: files done, files in all, the file; false stops the reload.
    using Progress = std::function<bool(int done, int total, const QString &file)>;

    /// Sets the folders and reloads (see reload()).
    bool setDirectories(const QStringList &directories, const Progress &progress = {});
    QStringList directories() const { return m_directories; }

    /**
     * Parses every `.idl` file again (after files were added, changed or removed). False when
     * @p progress stopped it; the library then keeps what it had.
     */
    bool reload(const Progress &progress = {});

    /// Structs usable as data port types, sorted by scoped name; "Timed" ones are flagged.
    QList<IdlDataType> dataTypes() const { return m_model.dataTypes(); }
    /// Interfaces usable as service port types (defined ones), sorted by scoped name.
    QList<IdlInterface> interfaces() const { return m_model.definedInterfaces(); }
    /// The file that declares `scopedName`, or an empty string.
    QString fileOf(const QString &scopedName) const;

    const IdlModel &model() const { return m_model; }
    const Profile::Diagnostics &diagnostics() const { return m_diagnostics; }

private:
    QStringList m_directories;
    IdlModel m_model;
    Profile::Diagnostics m_diagnostics;
};

} // namespace Codegen
