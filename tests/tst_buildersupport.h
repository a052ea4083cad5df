// SPDX-License-Identifier: MIT
#pragma once

// Shared by the Builder editor tests (tst_builderbasic, tst_builderpages): the fixture component
// and settings kept apart from the user's.

#include "rtcprofile.h"
#include "rtcxml.h"
#include "typecatalog.h"

#include <QCoreApplication>
#include <QFile>
#include <QSettings>
#include <QString>
#include <QTemporaryDir>

namespace BuilderTest {

/// The component in the Builder tests' data folder; a fixture that does not load ends the run.
inline Profile::RtcProfile fixture()
{
    QFile file(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/builder/component.xml"));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("missing fixture component.xml");
    Profile::Diagnostics diagnostics;
    return *Profile::readRtcXml(file.readAll(), file.fileName(), &diagnostics);
}

/**
 * Keeps the test's settings (IDL folders among them) in `dir`, apart from the user's, under the
 * organisation RtStudioTests and `applicationName`, with no user IDL folders.
 */
inline void isolateSettings(const QTemporaryDir &dir, const QString &applicationName)
{
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTests"));
    QCoreApplication::setApplicationName(applicationName);
    Builder::TypeCatalog::setUserDirectories({});
}

} // namespace BuilderTest
