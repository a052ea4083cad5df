// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

#include <optional>

namespace Corba {

/**
 * A path in rtshell's RTC tree: `/` → name servers (`localhost`, `host:2809`) → naming contexts
 * (`id.kind`) → objects (`Name0.rtc`, `manager.mgr`), with an optional `:port` suffix on the last
 * element. A manager may be addressed directly with `corbaloc::host[:2810][/manager]`.
 */
struct RtPath
{
    QStringList elements; ///< server first; empty for the root
    QString port; ///< port name after ':' on the last element, or empty
    QString corbaloc; ///< set (normalised, `corbaloc:iiop:host:port/key`) for direct addresses

    bool isRoot() const { return elements.isEmpty() && corbaloc.isEmpty(); }
    bool isDirect() const { return !corbaloc.isEmpty(); }
    /// The name-server element (`localhost:2809`), empty for the root.
    QString server() const { return elements.value(0); }
    /// `corbaloc:iiop:HOST:PORT/NameService` for the server (port 2809 when not given).
    QString nameServiceAddress() const;
    /// The naming-context elements below the server.
    QStringList names() const { return elements.mid(1); }
    /// The path without its port suffix.
    RtPath withoutPort() const;
    /// `/srv/ctx.kind/Name.rtc:port`, or the corbaloc.
    QString toString() const;

    /**
     * Parses `text` relative to `currentDirectory` (itself an absolute path; empty = `/`),
     * resolving
     * `.` and `..`. Returns std::nullopt and sets `error` for malformed text.
     */
    static std::optional<RtPath> parse(const QString &text,
                                       const QString &currentDirectory = QString(),
                                       QString *error = nullptr);
    /// Normalises `corbaloc::host[:port][/key]` to `corbaloc:iiop:host:port/key` (2810, manager).
    static std::optional<QString> normaliseCorbaloc(const QString &text, QString *error = nullptr);

    bool operator==(const RtPath &other) const;
    bool operator!=(const RtPath &other) const { return !(*this == other); }
};

/// One address of a corbaloc URL as written: `iiop:1.2@host:2810`, `:host` (iiop), `rir:`.
struct CorbalocAddress
{
    QString protocol; ///< `iiop`, `rir` …; empty for the `:host` form of iiop
    QString version; ///< the GIOP version before `@` (`1.2`) of an iiop address
    bool hasVersion = false; ///< whether the address has `@` (with a version, or an empty one)
    QString hostPort; ///< `host`, `host:port` or `[v6 address]:port`; empty for `rir:`

    bool isIiop() const { return protocol.isEmpty() || protocol == QLatin1String("iiop"); }
    /// The host, an IPv6 address without its brackets.
    QString host() const;
    /// Whether a port follows the host (`host:` counts, with an empty port).
    bool hasPort() const;
    QString toString() const;
};

/// A `corbaloc:` URL split into its comma-separated addresses and its object key.
struct Corbaloc
{
    QList<CorbalocAddress> addresses;
    std::optional<QString> key; ///< what follows the first `/`; none when there is no `/`

    QString toString() const;
    /// The parts of @p text, or std::nullopt when it does not start with `corbaloc:` (any case).
    static std::optional<Corbaloc> parse(const QString &text);
};

/// @p reference with each `iiop` corbaloc address made `ssliop` (TLS); anything else unchanged.
QString corbalocOverTls(const QString &reference);

/**
 * @p reference with GIOP 1.2 for each corbaloc address that names no version (`corbaloc:iiop:h:p/k`
 * becomes `corbaloc:iiop:1.2@h:p/k`); anything else unchanged. With corbaloc's default 1.0, omniORB
 * opens a second connection for the references the object hands out (naming contexts, components).
 */
QString corbalocWithGiop12(const QString &reference);

} // namespace Corba
