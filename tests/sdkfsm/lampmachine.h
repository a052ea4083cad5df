// SPDX-License-Identifier: MIT
// A lamp as a Macho state machine, written against Macho's API only (rtm/Macho.h), so that the
// same scenario runs on the component SDK and on OpenRTM-aist's own Macho. Every action appends a
// line to lampTrace(); runLampScenario() drives the lamp through nested states, deferred
// transitions, events dispatched from handlers, shallow and deep history, boxes and events with
// arguments, and returns the trace (compared with sdkfsm/lamp.trace).
//
//   Top (Box: presses, last code)
//   ├── Off
//   ├── On (DEEPHISTORY, Box: dims)        init → Dim
//   │   ├── Dim
//   │   └── Bright (HISTORY)                init → Warm
//   │       ├── Warm
//   │       └── Cold
//   └── Broken (PERSISTENT Box: failures)  init(int reason)
#pragma once

#include <rtm/Macho.h>

#include <sstream>
#include <string>
#include <vector>

namespace Lamp
{
inline std::vector<std::string> &lampTrace()
{
    static std::vector<std::string> lines;
    return lines;
}

inline void note(const std::string &line)
{
    lampTrace().push_back(line);
}

inline std::string number(long value)
{
    std::ostringstream text;
    text << value;
    return text.str();
}

struct Off;
struct On;
struct Dim;
struct Bright;
struct Warm;
struct Cold;
struct Broken;

TOPSTATE(Top)
{
    struct Box
    {
        Box()
            : presses(0)
            , lastCode(0)
        {
        }
        int presses;
        long lastCode;
    };

    STATE(Top);

    virtual void press() { note("Top.press ignored"); }
    virtual void toggle() { note("Top.toggle ignored"); }
    virtual void code(long value)
    {
        box().lastCode = value;
        note("Top.code " + number(value));
    }
    virtual void mix(int level, std::string colour) { note("Top.mix " + number(level) + " " + colour); }
    virtual void fail(int reason) { note("Top.fail " + number(reason) + " ignored"); }
    virtual void repair() { note("Top.repair ignored"); }
    virtual void dim() { note("Top.dim ignored"); }

private:
    void entry() override { note("Top.entry"); }
    void exit() override { note("Top.exit"); }
    void init() override
    {
        note("Top.init");
        setState<Off>();
    }
};

SUBSTATE(Off, Top)
{
    STATE(Off);
    void press() override
    {
        ++TOP::box().presses;
        note("Off.press");
        setState<On>();
        note("Off.press done");
    }

private:
    void entry() override { note("Off.entry"); }
    void exit() override { note("Off.exit"); }
    void init() override { note("Off.init"); }
};

SUBSTATE(On, Top)
{
    struct Box
    {
        Box()
            : dims(0)
        {
        }
        int dims;
    };

    STATE(On);
    DEEPHISTORY();

    void fail(int reason) override
    {
        note("On.fail " + number(reason));
        setState<Broken>(reason);
    }
    void dim() override
    {
        ++box().dims;
        note("On.dim " + number(box().dims));
        setState<Dim>();
    }

private:
    void entry() override { note("On.entry"); }
    void exit() override { note("On.exit"); }
    void init() override
    {
        note("On.init");
        setState<Dim>();
    }
};

SUBSTATE(Dim, On)
{
    STATE(Dim);
    void press() override
    {
        ++TOP::box().presses;
        note("Dim.press");
        setStateHistory<Bright>();
    }

private:
    void entry() override { note("Dim.entry"); }
    void exit() override { note("Dim.exit"); }
    void init() override { note("Dim.init"); }
};

SUBSTATE(Bright, On)
{
    STATE(Bright);
    HISTORY();

    void press() override
    {
        ++TOP::box().presses;
        note("Bright.press, dims " + number(On::box().dims));
        setState<Off>();
    }

private:
    void entry() override { note("Bright.entry"); }
    void exit() override { note("Bright.exit"); }
    void init() override
    {
        note("Bright.init");
        setState<Warm>();
    }
};

SUBSTATE(Warm, Bright)
{
    STATE(Warm);
    void toggle() override
    {
        note("Warm.toggle");
        setState<Cold>();
    }
    // Records the code, changes state and sends itself another event: the event is handled by
    // the new state, after the transition.
    void code(long value) override
    {
        TOP::box().lastCode = value;
        note("Warm.code " + number(value));
        setState<Cold>();
        dispatch(Event(&TOP::toggle));
        note("Warm.code done");
    }

private:
    void entry() override { note("Warm.entry"); }
    void exit() override { note("Warm.exit"); }
    void init() override { note("Warm.init"); }
};

SUBSTATE(Cold, Bright)
{
    STATE(Cold);
    void toggle() override
    {
        note("Cold.toggle");
        setState<Warm>();
    }
    void mix(int level, std::string colour) override
    {
        note("Cold.mix " + number(level) + " " + colour);
        dispatch(Event(&TOP::code, long(level) * 10));
    }

private:
    void entry() override { note("Cold.entry"); }
    void exit() override { note("Cold.exit"); }
    void init() override { note("Cold.init"); }
};

SUBSTATE(Broken, Top)
{
    struct Box
    {
        Box()
            : failures(0)
        {
        }
        int failures;
    };

    STATE(Broken);
    PERSISTENT();

    void repair() override
    {
        note("Broken.repair");
        setStateHistory<On>();
    }
    void press() override
    {
        note("Broken.press, failures " + number(box().failures));
    }

private:
    void entry() override
    {
        ++box().failures;
        note("Broken.entry");
    }
    void exit() override { note("Broken.exit"); }
    void init() override { note("Broken.init"); }
    void init(int reason) { note("Broken.init " + number(reason)); }
};

/// Appends where the machine is: the current state and what isCurrent() says of its superstates.
inline void where(const Macho::Machine<Top> &lamp)
{
    note(std::string("= ") + lamp.currentState().name() + (On::isCurrent(lamp) ? " in On" : "")
         + (Bright::isCurrent(lamp) ? " in Bright" : "") + (On::isCurrentDirect(lamp) ? " (On itself)" : "")
         + ", presses " + number(lamp.box().presses) + ", code " + number(lamp.box().lastCode));
}

/// Runs the lamp through every feature and returns what happened, one line per action.
inline std::vector<std::string> runLampScenario()
{
    lampTrace().clear();
    {
        note("# start");
        Macho::Machine<Top> lamp;
        where(lamp);
        note("# press: Off -> On, whose init chooses Dim");
        lamp->press();
        where(lamp);
        note("# press in Dim: Bright has no history yet, so its init chooses Warm");
        lamp.dispatch(Macho::Event(&Top::press));
        where(lamp);
        note("# an event with an argument, a transition and an event dispatched from the handler");
        lamp.dispatch(Macho::Event(&Top::code, 7L));
        where(lamp);
        note("# toggle: Warm -> Cold");
        lamp->toggle();
        where(lamp);
        note("# two arguments; the handler dispatches an event handled by the same state");
        lamp.dispatch(Macho::Event(&Top::mix, 4, std::string("amber")));
        where(lamp);
        note("# dim, handled by On: Cold -> Dim, Bright keeps Cold as its history, On's box counts");
        lamp->dim();
        where(lamp);
        note("# press in Dim: Bright's shallow history is Cold");
        lamp->press();
        where(lamp);
        note("# fail, handled by On: to Broken with init(reason); On's deep history is Cold");
        lamp.dispatch(Macho::Event(&Top::fail, 3));
        where(lamp);
        note("# repair: On's deep history, On's init does not run; On's box starts again");
        lamp->repair();
        where(lamp);
        note("# Broken's box persists: fail again, then press in Broken");
        lamp->fail(5);
        lamp->press();
        where(lamp);
        note("# history was used up: repair enters On's history again (set by the last leave)");
        lamp->repair();
        where(lamp);
        note("# press in Cold (Bright handles it): Off; then an event Off does not handle");
        lamp->press();
        lamp->toggle();
        where(lamp);
        note("# an alias of Bright's history from outside the machine");
        note(std::string("Bright history ") + Bright::history(lamp).name());
        Bright::clearHistory(lamp);
        note(std::string("Bright history cleared ") + Bright::history(lamp).name());
        note("# the machine goes: every active state is left");
    }
    note("# end");
    return lampTrace();
}
} // namespace Lamp
