// SPDX-License-Identifier: MIT
#include "codegenerator.h"

#include "contextbuilder.h"
#include "rtcxml.h"
#include "templaterenderer.h"
#include "templateset.h"

#include <QFile>
#include <QFileInfo>
#include <QSet>

using namespace Profile;

namespace Codegen {

namespace {

Diagnostic generationError(const QString &file, const QString &message)
{
    return Diagnostic::error(file, 0, 0, message);
}

/// The item's keys laid over the context, for `forEach` entries.
QVariantMap overlay(QVariantMap context, const QVariantMap &item)
{
    for (auto it = item.cbegin(); it != item.cend(); ++it)
        context.insert(it.key(), it.value());
    return context;
}

} // namespace

CodeGenerator::CodeGenerator(const RtcProfile &profile, const IdlModel &idl)
    : m_profile(profile)
    , m_idl(idl)
{ }

bool CodeGenerator::isSafeRelativePath(const QString &path)
{
    if (path.isEmpty() || path.startsWith(QLatin1Char('/')) || path.contains(QLatin1Char('\\'))
        || path.contains(QLatin1Char(':')))
        return false;
    const QStringList parts = path.split(QLatin1Char('/'));
    return std::none_of(parts.cbegin(), parts.cend(), [](const QString &part) {
        return part.isEmpty() || part == QLatin1String(".") || part == QLatin1String("..");
    });
}

std::optional<QList<GeneratedFile>> CodeGenerator::generate(const QList<TargetLanguage> &languages,
                                                            Diagnostics *diagnostics) const
{
    Diagnostics problems;
    QList<GeneratedFile> files;
    const ContextBuilder builder(m_profile, m_idl);
    QStringList languageNames;
    for (const TargetLanguage language : languages)
        languageNames << targetLanguageProfileName(language);
    for (int i = 0; i < languages.size(); ++i) {
        std::optional<QVariantMap> context = builder.build(languages.at(i), &problems);
        if (!context)
            continue;
        context->insert(QStringLiteral("languages"), languageNames);
        // The common files describe the whole project; the first language's context is as good
        // as any for them, since they use only language-neutral keys.
        if (i == 0)
            renderSet(QStringLiteral("common"), *context, QString(), &files, &problems);
        renderSet(targetLanguageKey(languages.at(i)), *context, QString(), &files, &problems);
    }
    // The test component is written in C++ when the project has C++, else in Python.
    const std::optional<TargetLanguage> testLanguage = languages.contains(TargetLanguage::Cpp)
        ? std::optional(TargetLanguage::Cpp)
        : languages.contains(TargetLanguage::Python) ? std::optional(TargetLanguage::Python) : std::nullopt;
    if (m_testComponent && testLanguage && !hasErrors(problems)) {
        addTestComponent(*testLanguage, languageNames, &files, &problems);
    } else if (m_testComponent && !testLanguage) {
        // Asking for it without C++ or Python is no reason to refuse the project, but the user
        // should learn why test/ stayed empty.
        problems << Diagnostic::warning(
            QString(), 0, 0,
            QStringLiteral("the test component is generated in C++ or Python only; no test/ written"));
    }
    if (languages.isEmpty())
        problems << generationError(QString(), QStringLiteral("no target language chosen"));
    if (!hasErrors(problems)) {
        files << GeneratedFile {QStringLiteral("RTC.xml"), writeRtcXml(m_profile)};
        addIdlCopies(QString(), &files, &problems);
    }
    QSet<QString> seen;
    for (const GeneratedFile &file : std::as_const(files)) {
        if (seen.contains(file.path))
            problems << generationError(file.path, QStringLiteral("two templates write this file"));
        seen.insert(file.path);
    }
    if (diagnostics)
        diagnostics->append(problems);
    if (hasErrors(problems))
        return std::nullopt;
    return files;
}

RtcProfile CodeGenerator::testComponentProfile(const RtcProfile &profile)
{
    RtcProfile test = profile;
    test.basicInfo.name += QStringLiteral("Test");
    for (RtcDataPort &port : test.dataPorts) {
        if (port.kind() == RtcPortType::DataIn)
            port.portType = QStringLiteral("DataOutPort");
        else if (port.kind() == RtcPortType::DataOut)
            port.portType = QStringLiteral("DataInPort");
    }
    for (RtcServicePort &port : test.servicePorts) {
        for (RtcServiceInterface &iface : port.interfaces)
            iface.direction = iface.kind() == RtcDirection::Provided ? QStringLiteral("Required")
                                                                     : QStringLiteral("Provided");
    }
    return test;
}

void CodeGenerator::addTestComponent(TargetLanguage language, const QStringList &languageNames,
                                     QList<GeneratedFile> *files, Diagnostics *diagnostics) const
{
    // The test component is a project of its own under test/, with its own copies of the IDL,
    // so that it configures and builds without the component's tree.
    const RtcProfile test = testComponentProfile(m_profile);
    const QString prefix = QStringLiteral("test/");
    std::optional<QVariantMap> context = ContextBuilder(test, m_idl).build(language, diagnostics);
    if (!context)
        return;
    context->insert(QStringLiteral("languages"), languageNames);
    renderSet(targetLanguageKey(language), *context, prefix, files, diagnostics);
    addIdlCopies(prefix, files, diagnostics);
}

bool CodeGenerator::renderSet(const QString &key, const QVariantMap &context,
                              const QString &pathPrefix, QList<GeneratedFile> *files,
                              Diagnostics *diagnostics) const
{
    QString error;
    const std::optional<TemplateSet> set = TemplateSet::load(key, m_userTemplates, &error);
    if (!set) {
        diagnostics->append(generationError(QString(), error));
        return false;
    }
    bool ok = true;
    for (const TemplateEntry &entry : set->entries()) {
        QVariantList items {QVariantMap()};
        if (!entry.forEach.isEmpty())
            items = context.value(entry.forEach).toList();
        for (const QVariant &item : std::as_const(items)) {
            const QVariantMap local = overlay(context, item.toMap());
            const std::optional<QString> path = renderTemplate(entry.outputPattern, local, &error);
            const std::optional<QString> body = path
                ? renderTemplate(set->templateText(entry.templateName), local, &error)
                : std::nullopt;
            const QString origin = set->templateOrigin(entry.templateName);
            if (!body) {
                diagnostics->append(generationError(origin, error));
                ok = false;
            } else if (!isSafeRelativePath(*path)) {
                diagnostics->append(generationError(
                    origin,
                    QStringLiteral("output path '%1' would leave the project folder").arg(*path)));
                ok = false;
            } else {
                files->append(GeneratedFile {pathPrefix + *path, body->toUtf8()});
            }
        }
    }
    return ok;
}

bool CodeGenerator::addIdlCopies(const QString &pathPrefix, QList<GeneratedFile> *files,
                                 Diagnostics *diagnostics) const
{
    const ContextBuilder builder(m_profile, m_idl);
    bool ok = true;
    for (const QString &source : builder.projectIdlFiles()) {
        QFile file(source);
        if (!file.open(QIODevice::ReadOnly)) {
            diagnostics->append(generationError(
                source, QStringLiteral("cannot copy IDL file: %1").arg(file.errorString())));
            ok = false;
            continue;
        }
        files->append(GeneratedFile {
            pathPrefix + QStringLiteral("idl/") + QFileInfo(source).fileName(), file.readAll()});
    }
    return ok;
}

} // namespace Codegen
