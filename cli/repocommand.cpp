// SPDX-License-Identifier: MIT
#include "repocommand.h"

#include "componentpackager.h"
#include "repository.h"

namespace Cli {

namespace {

struct RepoOptions
{
    QString action;
    QString repository;
    QStringList operands;
    Packages::RepositoryConfig config;
    bool newKey = false;
    QString keyUserId = QStringLiteral("RT Studio component repository <repository@invalid>");
    bool replace = false;
};

bool isValueOption(const QString &arg)
{
    static const QStringList options {"--suite",      "--component", "--arch",  "--key",
                                      "--gnupg-home", "--origin",    "--label", "--key-uid"};
    return options.contains(arg);
}

void setOption(const QString &arg, const QString &value, RepoOptions *options)
{
    Packages::RepositoryConfig &config = options->config;
    if (arg == QLatin1String("--suite"))
        config.suite = value;
    else if (arg == QLatin1String("--component"))
        config.component = value;
    else if (arg == QLatin1String("--arch"))
        config.architectures << value.split(QLatin1Char(','), Qt::SkipEmptyParts);
    else if (arg == QLatin1String("--key"))
        config.signWith = value;
    else if (arg == QLatin1String("--gnupg-home"))
        config.gnupgHome = value;
    else if (arg == QLatin1String("--origin"))
        config.origin = value;
    else if (arg == QLatin1String("--label"))
        config.label = value;
    else
        options->keyUserId = value;
}

QString parseArguments(const QStringList &arguments, RepoOptions *options)
{
    for (int i = 0; i < arguments.size(); ++i) {
        const QString &arg = arguments.at(i);
        if (isValueOption(arg)) {
            if (i + 1 >= arguments.size())
                return QStringLiteral("%1 needs a value").arg(arg);
            setOption(arg, arguments.at(++i), options);
        } else if (arg == QLatin1String("--new-key")) {
            options->newKey = true;
        } else if (arg == QLatin1String("--replace")) {
            options->replace = true;
        } else if (arg.startsWith(QLatin1Char('-'))) {
            return QStringLiteral("unknown option '%1'").arg(arg);
        } else if (options->action.isEmpty()) {
            options->action = arg;
        } else if (options->repository.isEmpty()) {
            options->repository = arg;
        } else {
            options->operands << arg;
        }
    }
    static const QStringList actions {"init", "publish", "remove", "list", "show"};
    if (!actions.contains(options->action))
        return options->action.isEmpty()
            ? QStringLiteral("missing the action")
            : QStringLiteral("unknown action '%1'").arg(options->action);
    if (options->repository.isEmpty())
        return QStringLiteral("missing the repository folder");
    const bool needsOperands = options->action == QLatin1String("publish")
        || options->action == QLatin1String("remove") || options->action == QLatin1String("show");
    if (needsOperands && options->operands.isEmpty())
        return QStringLiteral("%1 needs at least one %2")
            .arg(options->action,
                 options->action == QLatin1String("publish") ? QStringLiteral("FILE.deb")
                                                             : QStringLiteral("NAME"));
    if (!needsOperands && !options->operands.isEmpty())
        return QStringLiteral("unexpected '%1'").arg(options->operands.first());
    return {};
}

QString typesOf(const Packages::IndexEntry &entry)
{
    const QString types = entry.control.value(Packages::Field::RtcTypes);
    return types.isEmpty() ? QStringLiteral("-") : types;
}

int list(const Packages::Repository &repository, Streams streams)
{
    QString error;
    const std::optional<QList<Packages::IndexEntry>> entries = repository.packages(&error);
    if (!entries) {
        streams.err << "rtctl repo list: " << error << '\n';
        return ExitProblems;
    }
    for (const Packages::IndexEntry &entry : *entries)
        streams.out << entry.package() << ' ' << entry.version() << ' ' << entry.architecture()
                    << ' ' << typesOf(entry) << '\n';
    return ExitOk;
}

int show(const Packages::Repository &repository, const QStringList &names, Streams streams)
{
    QString error;
    const std::optional<QList<Packages::IndexEntry>> entries = repository.packages(&error);
    if (!entries) {
        streams.err << "rtctl repo show: " << error << '\n';
        return ExitProblems;
    }
    int code = ExitOk;
    bool first = true;
    for (const QString &operand : names) {
        const QString name = operand.section(QLatin1Char('='), 0, 0);
        const QString version = operand.section(QLatin1Char('='), 1);
        bool found = false;
        for (const Packages::IndexEntry &entry : *entries) {
            if (entry.package() != name || (!version.isEmpty() && entry.version() != version))
                continue;
            if (!first)
                streams.out << '\n';
            first = false;
            found = true;
            streams.out << QString::fromUtf8(entry.control.toText());
        }
        if (!found) {
            streams.err << "rtctl repo show: " << repository.root() << ": no package " << operand
                        << '\n';
            code = ExitProblems;
        }
    }
    return code;
}

} // namespace

QString RepoCommand::summary() const
{
    return QStringLiteral(
        "a Debian repository of component packages: init, publish, remove, list, show");
}

QString RepoCommand::usage() const
{
    return QStringLiteral(
        "Usage:\n"
        "  rtctl repo init REPO [--suite S] [--component C] [--arch A]... [--key ID | --new-key]\n"
        "                       [--gnupg-home DIR] [--origin TEXT] [--label TEXT]\n"
        "  rtctl repo publish REPO FILE.deb... [--replace] [--key ID] [--gnupg-home DIR]\n"
        "  rtctl repo remove REPO NAME[=VERSION]... [--key ID] [--gnupg-home DIR]\n"
        "  rtctl repo list REPO\n"
        "  rtctl repo show REPO NAME[=VERSION]...\n\n"
        "REPO is a folder apt-get reads as a Debian repository, directly or through any static\n"
        "web server:\n"
        "  deb [signed-by=REPO/archive-key.gpg] file:REPO SUITE COMPONENT\n"
        "Its indexes (dists/SUITE/COMPONENT/binary-ARCH/Packages, .gz, .xz, and Release) are\n"
        "written again after every change and replace the old ones in one step; Release is\n"
        "signed into InRelease and Release.gpg with the OpenPGP key through gpg.\n\n"
        "  --suite S          suite (default stable); --component C (default main)\n"
        "  --arch A           architectures listed (default: this machine's; repeatable)\n"
        "  --key ID           sign with this key (kept in the repository's settings at init)\n"
        "  --new-key          init: create a signing key without passphrase (for trials) in\n"
        "                     --gnupg-home; --key-uid sets its user id\n"
        "  --gnupg-home DIR   GnuPG home holding the key (default: gpg's)\n"
        "  --replace          publish: replace a package of the same name, version, arch\n\n"
        "The public key is exported as REPO/archive-key.asc and REPO/archive-key.gpg. Without a\n"
        "key the repository is unsigned and apt refuses it.\n"
        "list prints NAME VERSION ARCH TYPES per package; show prints the control data,\n"
        "X-RTC-Profile-Id and the other X-RTC fields included.\n"
        "Exit codes: 0 done, 1 refused or failed (the repository unchanged), 2 usage error.\n");
}

int RepoCommand::run(const QStringList &arguments, Streams streams)
{
    RepoOptions options;
    const QString problem = parseArguments(arguments, &options);
    if (!problem.isEmpty())
        return usageError(problem, streams);
    Packages::Repository repository(options.repository);
    QString error;
    const QString prefix = QStringLiteral("rtctl repo %1: ").arg(options.action);
    if (options.action == QLatin1String("init")) {
        if (!repository.init(options.config, options.newKey ? options.keyUserId : QString(),
                             &error)) {
            streams.err << prefix << error << '\n';
            return ExitProblems;
        }
        const Packages::RepositoryConfig &config = repository.config();
        streams.out << "created " << repository.root() << " (" << config.suite << ' '
                    << config.component << ", " << config.architectures.join(QLatin1Char(' '))
                    << ")\n";
        if (config.signWith.isEmpty())
            streams.err << "warning: no signing key: apt refuses an unsigned repository\n";
        else
            streams.out << "signed with " << config.signWith << "; public key " << repository.root()
                        << "/archive-key.gpg\n";
        return ExitOk;
    }
    if (!repository.open(&error)) {
        streams.err << prefix << error << '\n';
        return ExitProblems;
    }
    repository.overrideSigning(options.config.signWith, options.config.gnupgHome);
    if (options.action == QLatin1String("list"))
        return list(repository, streams);
    if (options.action == QLatin1String("show"))
        return show(repository, options.operands, streams);
    if (options.action == QLatin1String("publish")) {
        const auto added = repository.publish(options.operands, options.replace, &error);
        if (!added) {
            streams.err << prefix << error << '\n';
            return ExitProblems;
        }
        for (const Packages::IndexEntry &entry : *added)
            streams.out << "published " << entry.package() << ' ' << entry.version() << ' '
                        << entry.architecture() << ' ' << entry.filename() << '\n';
        return ExitOk;
    }
    int code = ExitOk;
    for (const QString &operand : options.operands) {
        const auto removed = repository.remove(operand.section(QLatin1Char('='), 0, 0),
                                               operand.section(QLatin1Char('='), 1), &error);
        if (!removed) {
            streams.err << prefix << error << '\n';
            code = ExitProblems;
            continue;
        }
        for (const Packages::IndexEntry &entry : *removed)
            streams.out << "removed " << entry.package() << ' ' << entry.version() << ' '
                        << entry.architecture() << '\n';
    }
    return code;
}

} // namespace Cli
