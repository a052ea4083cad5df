// SPDX-License-Identifier: MIT
#include "certificateauthority.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QHostAddress>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>

namespace Deploy {

namespace {

constexpr int OpenSslTimeoutMs = 30000;

const QStringList EcKey {QStringLiteral("-newkey"), QStringLiteral("ec"), QStringLiteral("-pkeyopt"),
                         QStringLiteral("ec_paramgen_curve:P-256"), QStringLiteral("-nodes")};

bool validName(const QString &name)
{
    static const QRegularExpression pattern(QStringLiteral("^[A-Za-z0-9][A-Za-z0-9._-]{0,63}$"));
    return pattern.match(name).hasMatch();
}

bool restrictToOwner(const QString &path)
{
    return QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
}

QString subjectAltNames(const QString &name, const QStringList &hosts)
{
    QStringList names;
    for (const QString &host : QStringList {name} + hosts) {
        const QString entry = QHostAddress(host).isNull() ? QStringLiteral("DNS:") + host : QStringLiteral("IP:") + host;
        if (!names.contains(entry))
            names << entry;
    }
    return names.join(QLatin1Char(','));
}

} // namespace

CertificateAuthority::CertificateAuthority(const QString &folder)
    : m_folder(folder)
{ }

QString CertificateAuthority::certificatePath() const
{
    return QDir(m_folder).filePath(QStringLiteral("ca.pem"));
}

QString CertificateAuthority::keyPath() const
{
    return QDir(m_folder).filePath(QStringLiteral("ca.key"));
}

QString CertificateAuthority::issuedPath(const QString &name) const
{
    return QDir(m_folder).filePath(name + QStringLiteral(".pem"));
}

bool CertificateAuthority::exists() const
{
    return QFile::exists(certificatePath()) && QFile::exists(keyPath());
}

bool CertificateAuthority::runOpenSsl(const QStringList &arguments, QString *error) const
{
    const QString program = QStandardPaths::findExecutable(QStringLiteral("openssl"));
    if (program.isEmpty()) {
        *error = tr("openssl is not installed (Debian package openssl)");
        return false;
    }
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    if (!process.waitForFinished(OpenSslTimeoutMs)) {
        process.kill();
        process.waitForFinished();
        *error = tr("openssl %1 did not finish").arg(arguments.value(0));
        return false;
    }
    if (process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
        *error = tr("openssl %1 failed: %2")
                     .arg(arguments.value(0), QString::fromLocal8Bit(process.readAll()).trimmed());
        return false;
    }
    return true;
}

bool CertificateAuthority::init(const QString &name, int days, QString *error)
{
    if (exists()) {
        *error = tr("%1: there is a certificate authority already").arg(m_folder);
        return false;
    }
    if (name.trimmed().isEmpty() || name.contains(QLatin1Char('/'))) {
        *error = tr("\"%1\" cannot name a certificate authority (no '/', not empty)").arg(name);
        return false;
    }
    if (!QDir().mkpath(m_folder)) {
        *error = tr("%1: cannot create the folder").arg(m_folder);
        return false;
    }
    QFile::setPermissions(m_folder, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    QStringList arguments {QStringLiteral("req"), QStringLiteral("-x509")};
    arguments << EcKey
              << QStringList {QStringLiteral("-keyout"), keyPath(), QStringLiteral("-out"), certificatePath(),
                              QStringLiteral("-days"), QString::number(days), QStringLiteral("-subj"),
                              QStringLiteral("/CN=") + name, QStringLiteral("-addext"),
                              QStringLiteral("basicConstraints=critical,CA:TRUE"), QStringLiteral("-addext"),
                              QStringLiteral("keyUsage=critical,keyCertSign,cRLSign")};
    if (!runOpenSsl(arguments, error)) {
        QFile::remove(keyPath());
        QFile::remove(certificatePath());
        return false;
    }
    return restrictToOwner(keyPath());
}

bool CertificateAuthority::issue(const QString &name, int days, const QStringList &hosts, QString *path,
                                 QString *error)
{
    if (!exists()) {
        *error = tr("%1: no certificate authority there (rtctl tls init)").arg(m_folder);
        return false;
    }
    if (!validName(name)) {
        *error = tr("\"%1\" cannot name a certificate: letters, digits, '.', '-' and '_' only").arg(name);
        return false;
    }
    QTemporaryDir work;
    if (!work.isValid()) {
        *error = tr("cannot create a temporary folder");
        return false;
    }
    const QString key = work.filePath(QStringLiteral("key.pem"));
    const QString request = work.filePath(QStringLiteral("request.csr"));
    const QString certificate = work.filePath(QStringLiteral("certificate.pem"));
    const QString extensions = work.filePath(QStringLiteral("extensions.cnf"));
    QFile extensionFile(extensions);
    if (!extensionFile.open(QIODevice::WriteOnly)) {
        *error = tr("cannot write %1").arg(extensions);
        return false;
    }
    // One certificate per node or operator, used both to serve and to call.
    extensionFile.write(QStringLiteral("basicConstraints=critical,CA:FALSE\n"
                                       "keyUsage=critical,digitalSignature,keyEncipherment\n"
                                       "extendedKeyUsage=serverAuth,clientAuth\n"
                                       "subjectAltName=%1\n")
                            .arg(subjectAltNames(name, hosts))
                            .toUtf8());
    extensionFile.close();
    QStringList requestArguments {QStringLiteral("req")};
    requestArguments << EcKey
                     << QStringList {QStringLiteral("-keyout"), key, QStringLiteral("-out"), request,
                                     QStringLiteral("-subj"), QStringLiteral("/CN=") + name};
    const QStringList signArguments {QStringLiteral("x509"),    QStringLiteral("-req"),  QStringLiteral("-in"),
                                     request,                   QStringLiteral("-CA"),   certificatePath(),
                                     QStringLiteral("-CAkey"),  keyPath(),               QStringLiteral("-set_serial"),
                                     QStringLiteral("0x") + QString::number(qint64(QDateTime::currentMSecsSinceEpoch()), 16),
                                     QStringLiteral("-days"),   QString::number(days),   QStringLiteral("-extfile"),
                                     extensions,                QStringLiteral("-out"),  certificate};
    if (!runOpenSsl(requestArguments, error) || !runOpenSsl(signArguments, error))
        return false;
    QFile keyFile(key);
    QFile certificateFile(certificate);
    if (!keyFile.open(QIODevice::ReadOnly) || !certificateFile.open(QIODevice::ReadOnly)) {
        *error = tr("openssl wrote no key or certificate");
        return false;
    }
    const QString target = issuedPath(name);
    QFile output(target);
    if (!output.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        *error = tr("%1: cannot write: %2").arg(target, output.errorString());
        return false;
    }
    restrictToOwner(target);
    output.write(keyFile.readAll());
    output.write(certificateFile.readAll());
    if (!output.flush()) {
        *error = tr("%1: cannot write: %2").arg(target, output.errorString());
        return false;
    }
    if (path)
        *path = target;
    return true;
}

} // namespace Deploy
