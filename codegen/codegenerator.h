// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "idlmodel.h"
#include "rtcprofile.h"
#include "targetlanguage.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <optional>

namespace Codegen {

/// One file of a generated project, in memory.
struct GeneratedFile
{
    QString path; ///< relative to the project folder, `/`-separated
    QByteArray content;

    bool operator==(const GeneratedFile &other) const
    {
        return path == other.path && content == other.content;
    }
    bool operator!=(const GeneratedFile &other) const { return !(*this == other); }
};

/**
 * Renders a component project from an RTC Profile: the `common` templates (README.md, rtc.conf,
 * `<N>.conf`), the templates of each requested language, `RTC.xml` (written by writeRtcXml) and
 * copies of the non-standard IDL files the profile's types come from (into `idl/`).
 *
 * With setTestComponent(true), a C++ project also gets `test/`: a stand-alone project of the
 * component `<N>Test`, whose ports mirror the component's (each InPort an OutPort of the same
 * type and the other way round, each provided interface a required one and the other way
 * round), so that the component can be exercised by connecting the two.
 *
 * Generation happens in memory and is all-or-nothing: a name that is no identifier of a
 * language, a service interface type missing from the IDL, a broken template or an output path
 * that would leave the project folder returns nothing plus errors. Output is deterministic:
 * the same profile, IDL and templates always give the same bytes.
 */
class CodeGenerator
{
public:
    CodeGenerator(const Profile::RtcProfile &profile, const IdlModel &idl);

    /// A folder whose `<language>/` sub-folders override the built-in templates.
    void setUserTemplateFolder(const QString &folder) { m_userTemplates = folder; }

    /// Also generate the C++ test component under `test/` (off by default). Without C++ among
    /// the languages nothing is added and generate() reports a warning.
    void setTestComponent(bool on) { m_testComponent = on; }

    /// The profile of the test component of `profile`: named `<N>Test`, with every data port
    /// and service interface direction reversed.
    static Profile::RtcProfile testComponentProfile(const Profile::RtcProfile &profile);

    std::optional<QList<GeneratedFile>> generate(const QList<TargetLanguage> &languages,
                                                 Profile::Diagnostics *diagnostics) const;

    /// True when `path` is relative, `/`-separated, and has no empty, `.` or `..` part.
    static bool isSafeRelativePath(const QString &path);

private:
    bool renderSet(const QString &key, const QVariantMap &context, const QString &pathPrefix,
                   QList<GeneratedFile> *files, Profile::Diagnostics *diagnostics) const;
    bool addIdlCopies(const QString &pathPrefix, QList<GeneratedFile> *files,
                      Profile::Diagnostics *diagnostics) const;
    /// Writes the test component (testComponentProfile()) in @p language under test/.
    void addTestComponent(TargetLanguage language, const QStringList &languageNames, QList<GeneratedFile> *files,
                          Profile::Diagnostics *diagnostics) const;

    const Profile::RtcProfile &m_profile;
    const IdlModel &m_idl;
    QString m_userTemplates;
    bool m_testComponent = false;
};

} // namespace Codegen
