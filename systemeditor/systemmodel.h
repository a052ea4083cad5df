// SPDX-License-Identifier: MIT
#pragma once

#include "rtcprofile.h"
#include "rtsprofile.h"
#include "systemprofileinfo.h"

#include <QHash>
#include <QMap>
#include <QObject>
#include <QPointF>
#include <QSizeF>

#include <optional>

namespace SystemEditor {

/// What a port is, as far as drawing and connecting care.
enum class PortKind {
    DataIn, ///< rtc:DataPorts DataInPort
    DataOut, ///< rtc:DataPorts DataOutPort
    Service, ///< rtc:ServicePorts
    Unknown ///< listed in the system file but no RTC profile describes it (drawn as a data port)
};

/// A side of a component's box.
enum class PortSide { Left, Right, Top, Bottom };

/**
 * The direction a component faces (`rtsExt:Location @direction`). Right is the default: inputs
 * on the left, outputs on the right. Left mirrors it; Down turns left→top, right→bottom; Up
 * turns left→bottom, right→top.
 */
enum class Direction { Right, Left, Up, Down };

/// `RIGHT` / `LEFT` / `UP` / `DOWN` (any case) → the enum; anything else → Right.
Direction directionFromText(const QString &text);
/// The schema's upper-case text of a direction.
QString directionText(Direction direction);
/// Where a port declared on `side` (for the default Right direction) is drawn for `direction`.
PortSide rotatedSide(PortSide side, Direction direction);

/// One interface of a service port, from the RTC profile.
struct InterfaceInfo
{
    QString name;
    QString type; ///< IDL interface type
    QString instanceName; ///< rtc:instanceName (pairs provided with required interfaces)
    Profile::RtcDirection polarity = Profile::RtcDirection::Unknown; ///< Provided / Required

    bool operator==(const InterfaceInfo &other) const;
    bool operator!=(const InterfaceInfo &other) const { return !(*this == other); }
};

/// A port of a component instance as the editor sees it.
struct PortInfo
{
    /// The port's key within its component: the name the system file uses for it (RTSE writes
    /// `<instance>.<port>`), which connector ends refer to.
    QString name;
    QString profileName; ///< the port's name in the RTC profile (`out`); equals name when unknown
    PortKind kind = PortKind::Unknown;
    QString dataType; ///< data ports: e.g. `RTC::TimedLong`
    QList<InterfaceInfo> interfaces; ///< service ports
    PortSide profileSide = PortSide::Left; ///< rtcExt:position, or the default for the kind
    PortSide side = PortSide::Left; ///< profileSide turned by the component's direction
    bool described = false; ///< an RTC profile describes this port

    bool isDataPort() const { return kind != PortKind::Service; }

    bool operator==(const PortInfo &other) const;
    bool operator!=(const PortInfo &other) const { return !(*this == other); }
};

/// Where and how large a component is drawn (`rtsExt:Location`).
struct ComponentLayout
{
    QPointF position;
    QSizeF size {-1, -1}; ///< a negative width/height means "default size"
    Direction direction = Direction::Right;

    bool operator==(const ComponentLayout &other) const;
    bool operator!=(const ComponentLayout &other) const { return !(*this == other); }
};

/// Data-port or service-port connector.
enum class ConnectorKind { Data, Service };

/// One end of a connector: a component instance and one of its ports (PortInfo::name).
struct ConnectorEnd
{
    QString instanceName;
    QString portName;

    bool operator==(const ConnectorEnd &other) const;
    bool operator!=(const ConnectorEnd &other) const { return !(*this == other); }
};

/// A connector as the editor sees it.
struct ConnectorInfo
{
    QString id; ///< connectorId
    QString name;
    ConnectorKind kind = ConnectorKind::Data;
    ConnectorEnd source;
    ConnectorEnd target;
    QList<QPointF> bendPoints; ///< from the `BEND_POINT` property; empty = route freely
    /// The `BEND_POINT` entries by key: RT System Editor's route segment index (0 leaves the
    /// source port) → a point that segment passes through. See savedRouteCorners().
    QMap<int, QPointF> bendPointEntries;

    bool operator==(const ConnectorInfo &other) const;
    bool operator!=(const ConnectorInfo &other) const { return !(*this == other); }
};

/**
 * `BEND_POINT` property text as RT System Editor writes it, `{1:(x,y),2:(x,y)}` with integer
 * coordinates. The key is the index of a route segment and the point one it passes through; this
 * editor writes its route's corners in order from key 1, corner i being where segment i starts.
 */
QString bendPointsToText(const QList<QPointF> &points);
/// The points of a `BEND_POINT` text in key order; nothing when the text is malformed.
std::optional<QList<QPointF>> bendPointsFromText(const QString &text);
/// The entries of a `BEND_POINT` text by key; nothing when the text is malformed.
std::optional<QMap<int, QPointF>> bendPointEntriesFromText(const QString &text);

/**
 * The editing model of one RT system: an RTS profile plus, per component instance, the RTC
 * profile describing it when one is known (from the repository or the component's pathUri).
 *
 * Everything is keyed by stable value ids: components by instance name, ports by PortInfo::name
 * within their component, connectors by connector id. Views (the canvas, outlines, property
 * panes) query it and listen to its signals; they never change it directly. Every user edit is
 * one of the undo commands in secommands.h, which call the mutators below. Save and load work on
 * profile() only.
 *
 * Content the editor does not draw (unknown properties and elements, message sequences, groups,
 * execution contexts) stays in the profile untouched by every mutator.
 */
class SystemModel : public QObject
{
    Q_OBJECT

public:
    /// The property that stores a connector's bend points.
    static inline const QString BendPointProperty = QStringLiteral("BEND_POINT");

    explicit SystemModel(QObject *parent = nullptr);
    explicit SystemModel(Profile::RtsProfile profile, QObject *parent = nullptr);

    // ---- whole model -------------------------------------------------------------------------

    const Profile::RtsProfile &profile() const { return m_profile; }
    /// Replaces everything (emits reset()). `rtcProfiles` maps instance names to their RTC profile.
    void setProfile(Profile::RtsProfile profile,
                    QHash<QString, Profile::RtcProfile> rtcProfiles = {});
    /**
     * Takes the profile as it was just saved (new pathUris, dates); announces what differs.
     * Not an undoable edit: it records where the files now are.
     */
    void adoptSavedProfile(const Profile::RtsProfile &saved);
    /// Vendor, name, version, abstract, dates and required components of the system.
    SystemProfileInfo systemInfo() const;
    /// Applies the info: rewrites id, abstract, dates and each component's isRequired.
    void setSystemInfo(const SystemProfileInfo &info);
    /// Sets the system id text as it is (may be malformed; validation reports it).
    void setSystemId(const QString &id);
    void setAbstract(const std::optional<QString> &abstract);

    // ---- components --------------------------------------------------------------------------

    /// Instance names in file order.
    QStringList componentIds() const;
    bool hasComponent(const QString &instanceName) const;
    /// The component's system-file record, or null.
    const Profile::RtsComponent *component(const QString &instanceName) const;
    /// Position of the component in profile().components, or -1.
    int componentIndex(const QString &instanceName) const;
    /// The RTC profile describing the component, or null when none is known.
    const Profile::RtcProfile *rtcProfile(const QString &instanceName) const;
    /// All known RTC profiles by instance name.
    const QHash<QString, Profile::RtcProfile> &rtcProfiles() const { return m_rtcProfiles; }
    /// Gives (or replaces) the RTC profile of a component; emits componentChanged().
    void setRtcProfile(const QString &instanceName, const Profile::RtcProfile &rtc);

    /**
     * The component's ports: those the RTC profile lists (in its order: data ports, then
     * service ports), named as the system file names them; then ports the system file lists that
     * the RTC profile does not know (kind Unknown, or Service when listed as a service port).
     */
    QList<PortInfo> ports(const QString &instanceName) const;
    std::optional<PortInfo> port(const QString &instanceName, const QString &portName) const;
    ComponentLayout layout(const QString &instanceName) const;
    /// The name a new instance of `typeName` gets: `<typeName>0`, `<typeName>1`, … (first free).
    QString uniqueInstanceName(const QString &typeName) const;

    // ---- connectors --------------------------------------------------------------------------

    /// Connector ids: data-port connectors, then service-port connectors, each in file order.
    QStringList connectorIds() const;
    std::optional<ConnectorInfo> connector(const QString &connectorId) const;
    const Profile::RtsDataPortConnector *dataConnector(const QString &connectorId) const;
    const Profile::RtsServicePortConnector *serviceConnector(const QString &connectorId) const;
    /// Connectors with an end on the component (or on one port of it when `portName` is given).
    QStringList connectorsOf(const QString &instanceName, const QString &portName = {}) const;
    bool isPortConnected(const QString &instanceName, const QString &portName) const;

    // ---- mutators (for undo commands) --------------------------------------------------------

    /// Inserts a component (at `index`, or at the end); false when the name is taken or empty.
    bool addComponent(const Profile::RtsComponent &component,
                      const std::optional<Profile::RtcProfile> &rtc = std::nullopt,
                      int index = -1);
    /// Removes the component only (its connectors stay; commands remove them first).
    bool removeComponent(const QString &instanceName);
    /// Replaces the component record with the same instance name (configuration, ports, …).
    bool setComponent(const Profile::RtsComponent &component);
    bool moveComponent(const QString &instanceName, const QPointF &position);
    bool resizeComponent(const QString &instanceName, const QSizeF &size);
    bool setDirection(const QString &instanceName, Direction direction);
    /// Sets (or removes) the whole `rtsExt:Location` record; undo uses it to restore exactly.
    bool setLocation(const QString &instanceName,
                     const std::optional<Profile::RtsLocation> &location);
    /**
     * Renames an instance. Its `<old>.` port names, the connector ends, group members,
     * composite and EC participants and message-sequence targets follow. False when `newName`
     * is taken or empty.
     */
    bool renameComponent(const QString &oldName, const QString &newName);
    bool setConfigurationSets(const QString &instanceName,
                              const QList<Profile::RtsConfigurationSet> &sets,
                              const std::optional<QString> &activeSet);

    /// Inserts a connector; false when its id is taken or empty. `index` -1 appends.
    bool addDataConnector(const Profile::RtsDataPortConnector &connector, int index = -1);
    bool addServiceConnector(const Profile::RtsServicePortConnector &connector, int index = -1);
    bool removeConnector(const QString &connectorId);
    /// Replaces the connector with the same id (name, types, properties …); kind must match.
    bool setDataConnector(const Profile::RtsDataPortConnector &connector);
    bool setServiceConnector(const Profile::RtsServicePortConnector &connector);
    /// Writes the `BEND_POINT` property (removed when `points` is empty).
    bool setBendPoints(const QString &connectorId, const QList<QPointF> &points);
    /// Index of the connector within its list (data or service), or -1.
    int connectorIndex(const QString &connectorId) const;

signals:
    void componentAdded(const QString &instanceName);
    void componentAboutToBeRemoved(const QString &instanceName);
    void componentRemoved(const QString &instanceName);
    /// Anything about the component changed (layout, ports, configuration, RTC profile …).
    void componentChanged(const QString &instanceName);
    void componentRenamed(const QString &oldName, const QString &newName);
    void connectorAdded(const QString &connectorId);
    void connectorAboutToBeRemoved(const QString &connectorId);
    void connectorRemoved(const QString &connectorId);
    void connectorChanged(const QString &connectorId);
    /// Id, abstract, dates or required flags changed.
    void systemInfoChanged();
    /// Everything was replaced; views rebuild from scratch.
    void reset();

private:
    Profile::RtsComponent *mutableComponent(const QString &instanceName);
    Profile::RtsPortConnector *mutableConnector(const QString &connectorId);
    Profile::RtsLocation &ensureLayout(Profile::RtsComponent &component);
    void renameReferences(const QString &oldName, const QString &newName);

    Profile::RtsProfile m_profile;
    QHash<QString, Profile::RtcProfile> m_rtcProfiles;
};

} // namespace SystemEditor
