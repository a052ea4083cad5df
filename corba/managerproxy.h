// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"

#include <QString>
#include <QStringList>

#include <optional>

#include <vector>

namespace Corba {

/**
 * A live RTM::Manager (OpenRTM-aist 2.x wire interface), addressed by object reference. Every
 * operation of the IDL is available; objects come back as IOR strings. Calls run under the
 * configured timeout and throw Corba::Error naming `path`; a ReturnCode_t other than RTC_OK
 * becomes Error::Kind::Refused.
 */
class ManagerProxy
{
public:
    ManagerProxy(QString ior, QString path);

    QString ior() const { return m_ior; }
    QString path() const { return m_path; }
    /// The name the RTC tree gives a manager's slave number @p index (`slave0.mgr`).
    static QString slaveName(int index) { return QStringLiteral("slave%1.mgr").arg(index); }

    void loadModule(const QString &pathName, const QString &initFunction) const;
    void unloadModule(const QString &pathName) const;
    std::vector<Properties> loadableModules() const;
    std::vector<Properties> loadedModules() const;
    std::vector<Properties> factoryProfiles() const;
    /**
     * `create_component("Type?k=v&...")`; returns the new component's IOR. Refused when nil, with
     * the manager's reason (its profile's `last_error`) when it gives one.
     */
    QString createComponent(const QString &moduleName) const;
    /// What createComponents() made: the new components' IORs in request order and, when there are
    /// fewer than requests, the refusal of the next one (as createComponent() would throw it).
    struct Created
    {
        QStringList iors;
        QString refusal;
    };
    /**
     * rtmanager's `create_components`: what createComponent() for each of @p requests in turn up
     * to the first refusal would make, in one call (waited for as long as those calls would be).
     * std::nullopt when the manager has no such operation (OpenRTM-aist's).
     */
    std::optional<Created> createComponents(const QStringList &requests) const;
    /**
     * `delete_component(instanceName)`. A master (OpenRTM-aist's as rtmanager) deletes only the
     * components it hosts itself; when it refuses, the slave that hosts the component is asked.
     * Returns the path of the manager that deleted it (this one's, or `<path>/slaveN.mgr`).
     */
    QString deleteComponent(const QString &instanceName) const;
    QStringList components() const;
    std::vector<ComponentInfo> componentProfiles() const;
    QStringList componentsByName(const QString &name) const;
    Properties profile() const;
    Properties configuration() const;
    void setConfiguration(const QString &name, const QString &value) const;
    bool isMaster() const;
    QStringList masterManagers() const;
    void addMasterManager(const QString &managerIor) const;
    void removeMasterManager(const QString &managerIor) const;
    QStringList slaveManagers() const;
    void addSlaveManager(const QString &managerIor) const;
    void removeSlaveManager(const QString &managerIor) const;
    void fork() const;
    void shutdown() const;
    void restart() const;
    /// get_service(name); an empty string for a nil reference.
    QString service(const QString &name) const;

private:
    QString refusalReason(const QString &request) const;
    /// The message of a refused create: "<path>: could not create '<request>' (<reason>)".
    /// checkReturnCode(), with the manager's last_error in the message of a refusal.
    void checkWithReason(int code, const QString &operation) const;
    QString refusal(const QString &request, const QString &reason) const;

    QString m_ior;
    QString m_path;
};

} // namespace Corba
