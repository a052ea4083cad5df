// SPDX-License-Identifier: MIT
#include "idlcommand.h"

#include "idlparser.h"
#include "installation.h"
#include "pythonstubwriter.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

using namespace Codegen;

namespace Cli {

namespace {

struct IdlOptions
{
    QString language;
    QStringList includeDirs;
    QString outputDir = QStringLiteral(".");
    QStringList files;
};

/// Reads the command line into `options`; returns the usage problem, or an empty string.
QString parseArguments(const QStringList &arguments, IdlOptions *options)
{
    for (int i = 0; i < arguments.size(); ++i) {
        QString arg = arguments.at(i);
        // -IDIR as omniidl takes it, besides -I DIR.
        if (arg.startsWith(QLatin1String("-I")) && arg.size() > 2) {
            options->includeDirs << arg.mid(2);
            continue;
        }
        if (arg == QLatin1String("--lang") || arg == QLatin1String("-I")
            || arg == QLatin1String("-o") || arg == QLatin1String("--output")) {
            if (i + 1 >= arguments.size())
                return QStringLiteral("%1 needs a value").arg(arg);
            const QString value = arguments.at(++i);
            if (arg == QLatin1String("--lang"))
                options->language = value;
            else if (arg == QLatin1String("-I"))
                options->includeDirs << value;
            else
                options->outputDir = value;
        } else if (arg.startsWith(QLatin1Char('-'))) {
            return QStringLiteral("unknown option %1").arg(arg);
        } else {
            options->files << arg;
        }
    }
    if (options->language.isEmpty())
        return QStringLiteral("missing --lang");
    if (options->language != QLatin1String("python"))
        return QStringLiteral("unknown language '%1' (python is the one there is)")
            .arg(options->language);
    if (options->files.isEmpty())
        return QStringLiteral("missing FILE.idl");
    return QString();
}

bool writeFile(const QString &path, const QString &text, QTextStream &err)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text.toUtf8()) < 0 || !file.commit()) {
        err << path << ": error: " << file.errorString() << '\n';
        return false;
    }
    return true;
}

} // namespace

QString IdlCommand::summary() const
{
    return QStringLiteral(
        "compile IDL files to Python modules for Python components (omniORBpy's layout)");
}

QString IdlCommand::usage() const
{
    return QStringLiteral(
        "Usage:\n"
        "  rtctl idl --lang python [-I DIR]... [-o OUTDIR] FILE.idl...\n\n"
        "  --lang python     the language to write (as omniidl -bpython)\n"
        "  -I DIR            a folder where #include looks (repeatable); OpenRTM's IDL is always "
        "searched\n"
        "  -o, --output DIR  where to write (default: the current folder)\n\n"
        "Writes <file>_idl.py for each file and a package per IDL module (<Module>/ and\n"
        "<Module>__POA/), which RT Studio's Python runtime uses instead of omniORBpy.\n"
        "Exit codes: 0 written, 1 problems in the IDL (nothing written), 2 usage error.\n");
}

int IdlCommand::run(const QStringList &arguments, Streams streams)
{
    IdlOptions options;
    const QString problem = parseArguments(arguments, &options);
    if (!problem.isEmpty())
        return usageError(problem, streams);
    IdlParser parser;
    parser.setSearchDirectories(options.includeDirs
                                + QStringList {Installation::bundledIdlDirectory()});
    QStringList texts;
    bool ok = true;
    for (const QString &path : std::as_const(options.files)) {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) {
            streams.err << path << ": error: " << file.errorString() << '\n';
            return ExitProblems;
        }
        texts << QString::fromUtf8(file.readAll());
        ok = parser.parseFile(path) && ok;
    }
    for (const Profile::Diagnostic &diagnostic : parser.diagnostics())
        streams.err << diagnostic.toString() << '\n';
    if (!ok)
        return ExitProblems;
    const QMap<QString, QString> files
        = PythonStubWriter(parser.model()).write(options.files, texts);
    for (auto it = files.constBegin(); it != files.constEnd(); ++it) {
        const QString path = QDir(options.outputDir).filePath(it.key());
        if (!writeFile(path, it.value(), streams.err))
            return ExitProblems;
        streams.out << "wrote " << path << '\n';
    }
    return ExitOk;
}

} // namespace Cli
