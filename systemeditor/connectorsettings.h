// SPDX-License-Identifier: MIT
#pragma once

#include "rtsconnector.h"

#include <QCoreApplication>
#include <QList>
#include <QPair>
#include <QStringList>

namespace SystemEditor {

class SystemModel;

/**
 * Which port of a data connector calls `connect()`. A system file records it as the connector's
 * source end (rtshell's rtresurrect and the restore engine connect from the source port), so
 * InToOut means the InPort is `sourceDataPort` and the OutPort `targetDataPort`.
 */
enum class ConnectDirection { OutToIn, InToOut };

/// The buffer settings of one side (`dataport.outport.buffer.*` or `dataport.inport.buffer.*`).
/// Empty text means "not set" (the component's default applies; nothing is written).
struct BufferSettings
{
    QString length; ///< integer > 0
    QString fullPolicy; ///< overwrite | do_nothing | block
    QString writeTimeout; ///< seconds, number ≥ 0
    QString emptyPolicy; ///< readback | do_nothing | block
    QString readTimeout; ///< seconds, number ≥ 0

    bool operator==(const BufferSettings &other) const;
    bool operator!=(const BufferSettings &other) const { return !(*this == other); }
};

/**
 * Every field of the reference's data-connector dialog, as a value.
 *
 * fromConnector() reads a connector's RTS attributes (dataType, interfaceType, dataflowType,
 * subscriptionType, pushInterval) and its standard `dataport.*` properties; applyTo() writes
 * them back (attributes plus properties; a field that is empty or disabled by the enabling rules
 * is removed). Properties that are not standard keys are the free properties; `BEND_POINT`
 * belongs to the drawing and is neither shown nor touched. Values are kept as text so that a bad
 * one is reported by validate(), never lost.
 */
struct ConnectorSettings
{
    Q_DECLARE_TR_FUNCTIONS(ConnectorSettings)

public:
    static constexpr int MaxNameLength = 255;

    QString name;
    QString dataType; ///< e.g. RTC::TimedLong (`dataType`, `dataport.data_type`)
    QString interfaceType; ///< corba_cdr, shared_memory, direct …
    QString marshalingType; ///< e.g. cdr (both `dataport.{out,in}port.marshaling_type`)
    QString dataflowType; ///< push | pull | duplex
    QString subscriptionType; ///< push only: flush | new | periodic
    QString pushRate; ///< Hz, periodic only (`pushInterval`, `dataport.push_rate`)
    QString pushPolicy; ///< new/periodic only: all | fifo | skip | new
    QString skipCount; ///< push policy skip: integer ≥ 0
    QString timestampPolicy; ///< on_write | on_send | on_received | on_read
    ConnectDirection connectDirection = ConnectDirection::OutToIn;
    BufferSettings outBuffer;
    BufferSettings inBuffer;
    QList<QPair<QString, QString>> freeProperties; ///< name/value, names unique

    /// The dialog's defaults for a new connector between `outPort` and `inPort`: name
    /// `<out>_<in>` (port names without their `instance.` prefix), corba_cdr, push, flush,
    /// 1000 Hz, all, skip 0, on_write; buffers unset.
    static ConnectorSettings defaults(const QString &outPort, const QString &inPort,
                                      const QString &dataType);
    /// Reads a connector; the connect direction needs `model` to tell the InPort end (without
    /// one the ends are taken as out → in).
    static ConnectorSettings fromConnector(const Profile::RtsDataPortConnector &connector,
                                           const SystemModel *model = nullptr);
    /**
     * Writes the settings into `connector` (id and unrelated content untouched). When the connect
     * direction differs from the connector's (judged with `model` as in fromConnector()), the
     * ends swap and the bend points reverse so that the drawn route stays the same.
     */
    void applyTo(Profile::RtsDataPortConnector &connector,
                 const SystemModel *model = nullptr) const;
    /// The direction the connector's ends record (see fromConnector()).
    static ConnectDirection directionOf(const Profile::RtsDataPortConnector &connector,
                                        const SystemModel *model);

    // The reference's enabling rules.
    bool isSubscriptionTypeEnabled() const;
    bool isPushRateEnabled() const;
    bool isPushPolicyEnabled() const;
    bool isSkipCountEnabled() const;

    /// Problems with the enabled fields; empty when the settings can be applied.
    QStringList validate() const;

    /// The standard ConnectorProfile keys this value maps (all `dataport.*`).
    static QStringList standardKeys();

    static QStringList interfaceTypes();
    static QStringList dataflowTypes();
    static QStringList subscriptionTypes();
    static QStringList pushPolicies();
    static QStringList timestampPolicies();
    static QStringList fullPolicies();
    static QStringList emptyPolicies();
    /// A short text for a direction ("OutPort → InPort").
    static QString directionText(ConnectDirection direction);

    bool operator==(const ConnectorSettings &other) const;
    bool operator!=(const ConnectorSettings &other) const { return !(*this == other); }
};

/// Turns a connector around (its target becomes the source end), keeping the drawn route: the
/// bend points reverse with the ends.
void reverseConnectorEnds(Profile::RtsPortConnector &connector);

} // namespace SystemEditor
