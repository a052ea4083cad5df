// SPDX-License-Identifier: MIT
#include "tlscommand.h"

#include "certificateauthority.h"
#include "clienttls.h"
#include "localruntime.h"
#include "tlstransport.h"

namespace Cli {

namespace {

constexpr int DefaultAuthorityDays = 3650;
constexpr int DefaultCertificateDays = 825;

// What one certificate says, one line each; false when it cannot be used now.
bool describe(const QString &path, QTextStream &out, QTextStream &err)
{
    Tls::CertificateInfo info;
    std::string error;
    if (!Tls::readCertificate(path.toStdString(), &info, &error)) {
        err << "rtctl tls: " << QString::fromStdString(error) << '\n';
        return false;
    }
    const QString state = info.expired ? QStringLiteral("EXPIRED")
        : info.notYetValid            ? QStringLiteral("NOT YET VALID")
                                      : QStringLiteral("valid");
    out << path << '\n'
        << "  subject   " << QString::fromStdString(info.subject) << '\n'
        << "  issuer    " << QString::fromStdString(info.issuer) << '\n'
        << "  valid     " << QString::fromStdString(info.notBefore) << " to " << QString::fromStdString(info.notAfter)
        << " (" << state << ")\n"
        << "  kind      " << (info.authority ? "certificate authority" : "node or operator") << '\n';
    return !info.expired && !info.notYetValid;
}

} // namespace

QString TlsCommand::summary() const
{
    return QStringLiteral("create a certificate authority and certificates for TLS; show them");
}

QString TlsCommand::usage() const
{
    return QStringLiteral(
        "Usage: rtctl tls init DIR [--name NAME] [--days N]\n"
        "       rtctl tls issue DIR NAME [--host HOST]... [--days N]\n"
        "       rtctl tls show [FILE...]\n\n"
        "TLS for managers, name servers, components and tools, with OpenRTM-aist's keys:\n"
        "  corba.ssl.certificate_authority_file  DIR/ca.pem (every node and operator trusts it)\n"
        "  corba.ssl.key_file                    DIR/NAME.pem (a node's or an operator's key and certificate)\n"
        "  corba.ssl.key_file_password           (the keys made here have none)\n\n"
        "init   creates the authority in DIR (ca.pem, and ca.key readable by you only; keep it off the robots),\n"
        "       valid 3650 days unless --days says otherwise.\n"
        "issue  writes DIR/NAME.pem for a node (its host name) or an operator, signed by the authority, valid\n"
        "       825 days; --host adds a DNS name or an IP address the node is reached by.\n"
        "show   prints what each certificate says and exits 1 when one is expired or not yet valid; with no\n"
        "       FILE, the TLS settings rtctl uses: RTSTUDIO_TLS_CA, RTSTUDIO_TLS_KEY and\n"
        "       RTSTUDIO_TLS_KEY_PASSWORD when set, else the local runtime's when it runs with --tls.\n");
}

int TlsCommand::run(const QStringList &arguments, Streams streams)
{
    QStringList words;
    QStringList hosts;
    QString name = QStringLiteral("RT Studio certificate authority");
    int days = 0;
    for (int i = 0; i < arguments.size(); ++i) {
        const QString &argument = arguments.at(i);
        const bool takesValue = argument == QLatin1String("--days") || argument == QLatin1String("--host")
            || argument == QLatin1String("--name");
        if (!takesValue) {
            if (argument.startsWith(QLatin1String("--")))
                return usageError(QStringLiteral("unknown option %1").arg(argument), streams);
            words << argument;
            continue;
        }
        if (i + 1 >= arguments.size())
            return usageError(QStringLiteral("%1 needs a value").arg(argument), streams);
        const QString value = arguments.at(++i);
        if (argument == QLatin1String("--host")) {
            hosts << value;
        } else if (argument == QLatin1String("--name")) {
            name = value;
        } else {
            bool ok = false;
            days = value.toInt(&ok);
            if (!ok || days < 0)
                return usageError(QStringLiteral("--days needs a number of days"), streams);
        }
    }
    const QString action = words.value(0);
    words.removeFirst();
    if (action == QLatin1String("init"))
        return init(words, days > 0 ? days : DefaultAuthorityDays, name, streams);
    if (action == QLatin1String("issue"))
        return issue(words, arguments.contains(QStringLiteral("--days")) ? days : DefaultCertificateDays, hosts,
                     streams);
    if (action == QLatin1String("show"))
        return show(words, streams);
    return usageError(action.isEmpty() ? QStringLiteral("tls needs one of init, issue, show")
                                       : QStringLiteral("unknown action '%1'").arg(action),
                      streams);
}

int TlsCommand::init(const QStringList &words, int days, const QString &name, Streams streams) const
{
    if (words.size() != 1)
        return usageError(QStringLiteral("tls init needs the authority's folder"), streams);
    Deploy::CertificateAuthority authority(words.first());
    QString error;
    if (!authority.init(name, days, &error)) {
        streams.err << "rtctl tls: " << error << '\n';
        return ExitProblems;
    }
    describe(authority.certificatePath(), streams.out, streams.err);
    return ExitOk;
}

int TlsCommand::issue(const QStringList &words, int days, const QStringList &hosts, Streams streams) const
{
    if (words.size() != 2)
        return usageError(QStringLiteral("tls issue needs the authority's folder and a name"), streams);
    Deploy::CertificateAuthority authority(words.first());
    QString error;
    QString path;
    if (!authority.issue(words.at(1), days, hosts, &path, &error)) {
        streams.err << "rtctl tls: " << error << '\n';
        return ExitProblems;
    }
    describe(path, streams.out, streams.err);
    return ExitOk;
}

int TlsCommand::show(const QStringList &words, Streams streams) const
{
    QStringList files = words;
    if (files.isEmpty()) {
        const QString authority = qEnvironmentVariable("RTSTUDIO_TLS_CA");
        if (!authority.isEmpty()) {
            streams.out << "TLS from the environment\n";
            files << authority << qEnvironmentVariable("RTSTUDIO_TLS_KEY");
        } else if (const Deploy::LocalRuntimeTls local = Deploy::LocalRuntime().tls(); local.enabled) {
            streams.out << "TLS of the local runtime\n";
            files << local.certificateAuthorityFile << local.userKeyFile;
        } else {
            streams.out << "TLS off: plain TCP (set RTSTUDIO_TLS_CA and RTSTUDIO_TLS_KEY, or rtctl local start --tls)\n";
            return ExitOk;
        }
        files.removeAll(QString());
    }
    bool usable = true;
    for (const QString &file : std::as_const(files))
        usable = describe(file, streams.out, streams.err) && usable;
    return usable ? ExitOk : ExitProblems;
}

} // namespace Cli
