// SPDX-License-Identifier: MIT
#pragma once

#include "rtpath.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace Corba {

/// What a node of the RTC tree is.
enum class NodeType {
    Root, ///< `/`
    Server, ///< a name server
    Context, ///< a naming context (`myhost.host_cxt`)
    Component, ///< an RT-Component (`Name0.rtc`, or a manager's component)
    Manager, ///< an RTM::Manager (`manager.mgr`)
    Object, ///< another live object
    Zombie ///< a name whose object does not answer or is not of the expected type
};

/// "server", "context", "component", "manager", "object", "zombie".
QString nodeTypeName(NodeType type);

/// One node of the RTC tree; `children` are filled only by NamingBrowser::tree().
struct NamingNode
{
    QString name; ///< `id.kind`, or the server address
    NodeType type = NodeType::Object;
    QString path; ///< absolute rtshell path
    QString ior; ///< the object reference of objects and components
    QString reason; ///< why the node is a zombie, or why it is not answering
    std::vector<NamingNode> children;
    /// False when the object did not answer within the call timeout (stopped or busy); it keeps
    /// the type its name gives.
    bool answering = true;
};

/**
 * Browses name servers the way rtshell's RTC tree does. Every remote call uses the configured
 * timeout; failures are thrown as Corba::Error naming the path.
 */
class NamingBrowser
{
public:
    /// How much a listing asks the objects it finds.
    enum class Check {
        Objects, ///< each bound object is asked what it is; managers are asked for their components
        NamedObjects, ///< each bound object is asked what it is; managers are not listed
        NamesOnly ///< only name servers are asked: types come from the names' kinds (`rtc`, `mgr`)
    };

    /// Name servers listed in `RTCTREE_NAMESERVERS` (`;`-separated, `,` also accepted).
    static QStringList serversFromEnvironment();

    /**
     * The children of `path`: the servers (for `/`, from `rootServers`), the bindings of a server
     * or context (objects checked for liveness and type), or a manager's components and slaves.
     */
    static std::vector<NamingNode> list(const RtPath &path, const QStringList &rootServers = {});
    /// The node at `path` itself, checked; NotFound when the name is not bound.
    static NamingNode node(const RtPath &path);
    /**
     * `path` and everything below it up to `maxDepth` levels (negative: no limit). Objects are
     * checked concurrently, so objects that hang cost about one call timeout in all.
     */
    static NamingNode tree(const RtPath &path, int maxDepth = -1,
                           const QStringList &rootServers = {}, Check check = Check::Objects);
    /// The object reference (IOR) bound at `path` (or at its corbaloc).
    static QString resolve(const RtPath &path);
    /// Binds `ior` at `path` (its naming context must exist).
    static void bind(const RtPath &path, const QString &ior);
    /// Removes the binding at `path` (e.g. to clear a zombie).
    static void unbind(const RtPath &path);
};

} // namespace Corba
