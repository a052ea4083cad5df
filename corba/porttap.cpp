// SPDX-License-Identifier: MIT
#include "porttap.h"

#include "corbacall.h"
#include "portconnection.h"

#include <DataPort_OpenRTM.hh>

#include <QDateTime>
#include <QUuid>

#include <condition_variable>
#include <deque>
#include <mutex>

namespace Corba {

using namespace Internal;

namespace {

/// The root POA, its manager active so that this process's servants answer.
PortableServer::POA_ptr rootPoa()
{
    static std::once_flag once;
    static PortableServer::POA_var poa;
    std::call_once(once, [] {
        CORBA::Object_var object = orb()->resolve_initial_references("RootPOA");
        poa = PortableServer::POA::_narrow(object);
        PortableServer::POAManager_var manager = poa->the_POAManager();
        manager->activate();
    });
    return poa.in();
}

/// A tool's connector: rtcon's defaults (PortConnection::effectiveProperties), little-endian CDR as
/// OpenRTM-aist 2.x sends it, then what the caller gives.
Properties connectorProperties(const PortInfo &port, const Properties &given)
{
    Properties defaults = {{QStringLiteral("dataport.serializer.cdr.endian"), QStringLiteral("little")}};
    defaults += given;
    return PortConnection::effectiveProperties({port}, defaults);
}

bool isLittleEndian(const Properties &properties)
{
    // OpenRTM's rule: "big" only when the first listed byte order is big.
    return !propertyValue(properties, QStringLiteral("dataport.serializer.cdr.endian"),
                          QStringLiteral("little"))
                .trimmed()
                .startsWith(QLatin1String("big"), Qt::CaseInsensitive);
}

QString portStatusName(OpenRTM::PortStatus status)
{
    static const char *const names[]
        = {"PORT_OK", "PORT_ERROR", "BUFFER_FULL", "BUFFER_EMPTY", "BUFFER_TIMEOUT", "UNKNOWN_ERROR"};
    const int index = int(status);
    return index >= 0 && index < int(std::size(names)) ? QLatin1String(names[index])
                                                       : QString::number(index);
}

/// The InPortCdr object a PortTap's connector pushes into.
class TapServant : public POA_OpenRTM::InPortCdr
{
public:
    explicit TapServant(size_t capacity)
        : m_capacity(capacity)
    { }

    OpenRTM::PortStatus put(const OpenRTM::CdrData &data) override
    {
        PortSample sample {QByteArray(reinterpret_cast<const char *>(data.get_buffer()), int(data.length())),
                           QDateTime::currentMSecsSinceEpoch()};
        {
            std::lock_guard lock(m_mutex);
            if (m_queue.size() >= m_capacity) {
                m_queue.pop_front();
                ++m_dropped;
            }
            m_queue.push_back(std::move(sample));
        }
        m_arrived.notify_one();
        return OpenRTM::PORT_OK;
    }

    std::optional<PortSample> next(int timeoutMs)
    {
        std::unique_lock lock(m_mutex);
        if (!m_arrived.wait_for(lock, std::chrono::milliseconds(std::max(0, timeoutMs)),
                                [this] { return !m_queue.empty(); }))
            return std::nullopt;
        PortSample sample = std::move(m_queue.front());
        m_queue.pop_front();
        return sample;
    }

    bool wait(int timeoutMs)
    {
        std::unique_lock lock(m_mutex);
        return m_arrived.wait_for(lock, std::chrono::milliseconds(std::max(0, timeoutMs)),
                                  [this] { return !m_queue.empty(); });
    }

    quint64 dropped() const
    {
        std::lock_guard lock(m_mutex);
        return m_dropped;
    }

private:
    const size_t m_capacity;
    mutable std::mutex m_mutex;
    std::condition_variable m_arrived;
    std::deque<PortSample> m_queue;
    quint64 m_dropped = 0;
};

/// The connector of a tool (PortTap or PortFeed) and its removal.
struct ToolConnector
{
    PortInfo port;
    QString path;
    ConnectorInfo connector;
    bool open = false;

    void close()
    {
        if (!open)
            return;
        open = false;
        PortConnection::disconnect(port, connector.id, path);
    }

    void closeQuietly() noexcept
    {
        try {
            close();
        } catch (...) {
            // The port's process may be gone; there is nothing left to remove then.
        }
    }
};

QString toolConnectorName(const char *tool)
{
    return QStringLiteral("rtctl_%1_%2")
        .arg(QLatin1String(tool), QUuid::createUuid().toString(QUuid::Id128).left(8));
}

} // namespace

struct PortTap::Private
{
    TapServant *servant = nullptr;
    PortableServer::ObjectId_var id;
    ToolConnector connector;
    bool little = true;

    ~Private()
    {
        connector.closeQuietly();
        if (servant) {
            try {
                rootPoa()->deactivate_object(id.in());
            } catch (...) {
                // Already gone with the ORB.
            }
            servant->_remove_ref();
        }
    }
};

PortTap::PortTap(const PortInfo &port, const Properties &properties, const QString &path,
                 int queueLength)
    : d(std::make_unique<Private>())
{
    if (!port.isDataOut())
        throw Error(Error::Kind::Incompatible,
                    QStringLiteral("%1: not an OutPort (%2)").arg(path, port.portType()));
    Properties settings = connectorProperties(port, properties);
    d->little = isLittleEndian(settings);
    call(path, [&] {
        d->servant = new TapServant(size_t(std::max(1, queueLength)));
        d->id = rootPoa()->activate_object(d->servant);
        CORBA::Object_var object = rootPoa()->id_to_reference(d->id.in());
        setProperty(settings, QStringLiteral("dataport.corba_cdr.inport_ior"), toIor(object));
    });
    d->connector = {port, path,
                    PortConnection::connectAsGiven({port}, toolConnectorName("print"), QString(),
                                                   settings, path),
                    true};
}

PortTap::~PortTap() = default;

std::optional<PortSample> PortTap::next(int timeoutMs)
{
    return d->servant->next(timeoutMs);
}

bool PortTap::wait(int timeoutMs)
{
    return d->servant->wait(timeoutMs);
}

quint64 PortTap::dropped() const
{
    return d->servant->dropped();
}

bool PortTap::littleEndian() const
{
    return d->little;
}

void PortTap::close()
{
    d->connector.close();
}

struct PortFeed::Private
{
    ToolConnector connector;
    OpenRTM::InPortCdr_var target;
    bool little = true;

    ~Private() { connector.closeQuietly(); }
};

PortFeed::PortFeed(const PortInfo &port, const Properties &properties, const QString &path)
    : d(std::make_unique<Private>())
{
    if (!port.isDataIn())
        throw Error(Error::Kind::Incompatible,
                    QStringLiteral("%1: not an InPort (%2)").arg(path, port.portType()));
    const Properties settings = connectorProperties(port, properties);
    d->little = isLittleEndian(settings);
    d->connector = {port, path,
                    PortConnection::connectAsGiven({port}, toolConnectorName("inject"), QString(),
                                                   settings, path),
                    true};
    const QString ior = propertyValue(d->connector.connector.properties,
                                      QStringLiteral("dataport.corba_cdr.inport_ior"));
    if (ior.isEmpty())
        throw Error(Error::Kind::Refused,
                    QStringLiteral("%1: the port published no InPortCdr object").arg(path));
    call(path, [&] {
        CORBA::Object_var object = toObject(ior, path);
        d->target = OpenRTM::InPortCdr::_narrow(object);
    });
    if (CORBA::is_nil(d->target))
        throw Error(Error::Kind::Refused,
                    QStringLiteral("%1: the published object is no InPortCdr").arg(path));
}

PortFeed::~PortFeed() = default;

void PortFeed::put(const QByteArray &cdr)
{
    const QString &path = d->connector.path;
    const OpenRTM::PortStatus status = callServed(path, d->connector.port.ior, [&] {
        OpenRTM::CdrData data(CORBA::ULong(cdr.size()), CORBA::ULong(cdr.size()),
                              reinterpret_cast<CORBA::Octet *>(const_cast<char *>(cdr.constData())),
                              false);
        return d->target->put(data);
    });
    if (status != OpenRTM::PORT_OK)
        throw Error(Error::Kind::Refused,
                    QStringLiteral("%1: put: %2").arg(path, portStatusName(status)));
}

bool PortFeed::littleEndian() const
{
    return d->little;
}

void PortFeed::close()
{
    d->connector.close();
}

} // namespace Corba
