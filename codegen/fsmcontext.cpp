// SPDX-License-Identifier: MIT
// The state-machine half of ContextBuilder: EventPorts and their events become an OpenRTM-aist
// static FSM (rtm/StaticFSM.h) whose states are the events' sources and targets.
#include "contextbuilder.h"

#include <algorithm>

using namespace Profile;

namespace Codegen {

namespace {

/// The C++ type of an event's argument; RTC Builder writes OpenRTM's data types without the
/// `RTC::` scope (`TimedLong`).
QString eventArgumentType(const RtcEvent &event)
{
    const QString type = event.type.value_or(QString()).trimmed();
    if (type.isEmpty() || type.contains(QLatin1String("::")))
        return type;
    return QStringLiteral("RTC::") + type;
}

/// The guard function a transition calls: the condition itself when it is a name, otherwise one
/// named after the event (the condition's text then documents it).
QString guardName(const RtcEvent &event)
{
    const QString condition = event.condition.value_or(QString()).trimmed();
    if (condition.isEmpty())
        return QString();
    return isValidIdentifier(TargetLanguage::Cpp, condition) ? condition
                                                             : event.name + QStringLiteral("Guard");
}

Diagnostic eventError(const RtcDataPort &port, const RtcEvent &event, const QString &message)
{
    Diagnostic d = Diagnostic::error(QString(), event.location.line, event.location.column,
                                     QStringLiteral("Event '%1' of EventPort '%2': %3")
                                         .arg(event.name, port.name, message));
    d.object = port.name;
    return d;
}

struct Transition
{
    const RtcEvent *event;
    QString argumentType;
};

} // namespace

bool ContextBuilder::addFsm(TargetLanguage language, QVariantMap &context,
                            Diagnostics *diagnostics) const
{
    QVariantList eventPorts;
    QStringList states; // first appearance order; the first source is the initial state
    QHash<QString, QString> eventTypes; // event name -> argument type, one per name
    QStringList eventOrder;
    QHash<QString, QList<Transition>> transitionsFrom;
    QList<QPair<QString, QString>> guards; // name, argument type
    QHash<QString, QStringList> guardConditions;
    const qsizetype before = diagnostics->size();

    auto addState = [&](const QString &state) {
        if (!states.contains(state))
            states << state;
    };

    for (const RtcDataPort &port : m_profile.dataPorts) {
        if (port.kind() != RtcPortType::Event)
            continue;
        QVariantList events;
        for (const RtcEvent &event : port.events) {
            if (!isValidIdentifier(TargetLanguage::Cpp, event.name)) {
                diagnostics->append(eventError(port, event,
                                               QStringLiteral("the name must be a C++ identifier "
                                                              "(it names the event handler)")));
                continue;
            }
            bool statesValid = true;
            for (const QString &state : {event.source, event.target}) {
                if (!isValidIdentifier(TargetLanguage::Cpp, state) || state == QLatin1String("Top")) {
                    diagnostics->append(eventError(
                        port, event,
                        QStringLiteral("state '%1' must be a C++ identifier other than 'Top' (it "
                                       "names a state class)")
                            .arg(state)));
                    statesValid = false;
                }
            }
            if (!statesValid)
                continue;
            const QString type = eventArgumentType(event);
            const auto known = eventTypes.constFind(event.name);
            if (known != eventTypes.cend() && *known != type) {
                diagnostics->append(eventError(
                    port, event,
                    QStringLiteral("another event of that name carries '%1'; one event has one "
                                   "data type")
                        .arg(known->isEmpty() ? QStringLiteral("no data") : *known)));
                continue;
            }
            if (known == eventTypes.cend()) {
                eventTypes.insert(event.name, type);
                eventOrder << event.name;
            }
            addState(event.source);
            addState(event.target);
            transitionsFrom[event.source] << Transition {&event, type};
            const QString guard = guardName(event);
            if (!guard.isEmpty()) {
                const QPair<QString, QString> key(guard, type);
                if (!guards.contains(key))
                    guards << key;
                QStringList &conditions = guardConditions[guard];
                if (!conditions.contains(event.condition->trimmed()))
                    conditions << event.condition->trimmed();
            }
            // Several transitions share an event: the port binds it once.
            if (std::none_of(events.cbegin(), events.cend(), [&](const QVariant &bound) {
                    return bound.toMap().value(QStringLiteral("name")) == event.name;
                })) {
                events << QVariantMap {{QStringLiteral("name"), event.name},
                                       {QStringLiteral("literalName"),
                                        escapeStringLiteral(event.name)}};
            }
        }
        eventPorts << QVariantMap {
            {QStringLiteral("name"), port.name},
            {QStringLiteral("literalName"), escapeStringLiteral(port.name)},
            {QStringLiteral("variable"), port.variableName && !port.variableName->trimmed().isEmpty()
                                             ? *port.variableName
                                             : port.name},
            {QStringLiteral("events"), markFirstLast(events)}};
    }
    if (diagnostics->size() != before)
        return false;

    // Only C++ has OpenRTM's static FSM; the other languages keep their data-flow part.
    const bool hasFsm = language == TargetLanguage::Cpp && !eventPorts.isEmpty();
    context.insert(QStringLiteral("hasFsm"), hasFsm);
    context.insert(QStringLiteral("fsmFiles"), hasFsm ? QVariantList {QVariantMap()} : QVariantList());
    if (!hasFsm)
        return true;

    const QString fsmNamespace = m_profile.basicInfo.name + QStringLiteral("Fsm");
    QVariantList protocol;
    for (const QString &name : std::as_const(eventOrder)) {
        const QString type = eventTypes.value(name);
        protocol << QVariantMap {
            {QStringLiteral("name"), name},
            {QStringLiteral("declaration"),
             QStringLiteral("virtual void %1(%2) {}")
                 .arg(name, type.isEmpty() ? QString() : type + QStringLiteral(" /*data*/"))}};
    }
    QVariantList guardList;
    for (const auto &[name, type] : std::as_const(guards)) {
        const QString parameter = type.isEmpty() ? QString() : QStringLiteral("const %1& data").arg(type);
        // The condition's own text documents a guard that could not be named after it.
        const QString conditions = guardConditions.value(name) == QStringList {name}
            ? QString()
            : guardConditions.value(name).join(QStringLiteral(" / "));
        guardList << QVariantMap {
            {QStringLiteral("name"), name},
            {QStringLiteral("declaration"), QStringLiteral("bool %1(%2)").arg(name, parameter)},
            {QStringLiteral("definition"),
             QStringLiteral("bool Top::%1(%2)")
                 .arg(name, type.isEmpty() ? QString() : QStringLiteral("const %1& /*data*/").arg(type))},
            {QStringLiteral("hasConditions"), !conditions.isEmpty()},
            {QStringLiteral("conditions"), conditions}};
    }
    QVariantList stateList;
    for (const QString &state : std::as_const(states)) {
        // Transitions of one event from one state make one handler that tries them in the
        // profile's order (the first whose guard holds is taken).
        QList<Transition> transitions = transitionsFrom.value(state);
        std::stable_sort(transitions.begin(), transitions.end(),
                         [&](const Transition &a, const Transition &b) {
                             return eventOrder.indexOf(a.event->name) < eventOrder.indexOf(b.event->name);
                         });
        QVariantList handlers;
        for (int i = 0; i < transitions.size(); ++i) {
            const Transition &t = transitions.at(i);
            const QString parameter = t.argumentType.isEmpty() ? QString() : t.argumentType + QStringLiteral(" data");
            const QString guard = guardName(*t.event);
            handlers << QVariantMap {
                {QStringLiteral("declaration"), QStringLiteral("void %1(%2)").arg(t.event->name, parameter)},
                {QStringLiteral("definition"),
                 QStringLiteral("void %1::%2(%3)").arg(state, t.event->name, parameter)},
                {QStringLiteral("usesData"), !t.argumentType.isEmpty()},
                {QStringLiteral("target"), t.event->target},
                {QStringLiteral("hasGuard"), !guard.isEmpty()},
                {QStringLiteral("guardCall"),
                 QStringLiteral("%1(%2)").arg(guard, t.argumentType.isEmpty() ? QString()
                                                                              : QStringLiteral("data"))},
                {QStringLiteral("opens"), i == 0 || transitions.at(i - 1).event->name != t.event->name},
                {QStringLiteral("closes"),
                 i == transitions.size() - 1 || transitions.at(i + 1).event->name != t.event->name}};
        }
        QVariantList declared;
        for (const QVariant &h : std::as_const(handlers)) {
            if (h.toMap().value(QStringLiteral("opens")).toBool())
                declared << h;
        }
        stateList << QVariantMap {{QStringLiteral("name"), state},
                                  {QStringLiteral("handlers"), handlers},
                                  {QStringLiteral("hasHandlers"), !declared.isEmpty()},
                                  {QStringLiteral("declaredHandlers"), markFirstLast(declared)}};
    }
    context.insert(QStringLiteral("fsmNamespace"), fsmNamespace);
    context.insert(QStringLiteral("fsmMachineType"),
                   QStringLiteral("RTC::Machine<%1::Top>").arg(fsmNamespace));
    context.insert(QStringLiteral("fsmInitialState"), states.value(0));
    context.insert(QStringLiteral("fsmEvents"), markFirstLast(protocol));
    context.insert(QStringLiteral("fsmGuards"), markFirstLast(guardList));
    context.insert(QStringLiteral("fsmStates"), markFirstLast(stateList));
    context.insert(QStringLiteral("eventPorts"), markFirstLast(eventPorts));
    return true;
}

} // namespace Codegen
