# SPDX-License-Identifier: MIT
"""OpenRTM_aist.StaticFSM: hierarchical state machines declared as classes, as OpenRTM-aist-Python's
static FSM (after the Macho library) declares them.

A machine's top state is a class decorated with FSM_TOPSTATE; each substate is decorated with
FSM_SUBSTATE(parent) and answers the events its parents declare (an event is a method of the top
state; a substate overrides it, and the nearest state that does answers it). A state's own
onEntry / onExit are called as the machine enters and leaves it, its onInit when it is the target
of a transition (to go on into a substate). set_state(State(S)) in a handler makes the transition
once the handler returns; dispatch(Event(...)) in a handler queues an event after it. A state
class's nested class Data is its data box, reached from any substate with data(S). A state
decorated with deephistory, entered again, goes back to the innermost state it was left in.
"""

import collections
import threading

import RTC


class Link(object):
    """The base of state classes; the machine makes one object of each state class it enters."""

    _machine = None
    _parent_state = None
    _deep_history = False

    def set_state(self, state):
        """Transition to state (State(S)) when the running handler returns."""
        self._machine._set_pending(state)

    def dispatch(self, event):
        """Queues event (Event(Top.method, args…)) after the running one."""
        self._machine._queue_next(event)

    def data(self, state):
        """The data box of state (its class Data), or None when it has none."""
        return self._machine._box(state)

    def setStateHistory(self, state):
        self._machine._history[self._state_class()] = state

    def _state_class(self):
        return type(self)

    def onEntry(self):
        return RTC.RTC_OK

    def onExit(self):
        return RTC.RTC_OK

    def onInit(self):
        return RTC.RTC_OK


def _own(cls, name):
    """The method name of state cls itself (not inherited from its parents), or None."""
    return cls.__dict__.get("_own_methods", {}).get(name)


def FSM_TOPSTATE(cls):
    """Declares cls the top state of a machine."""
    return _state_class(cls, None)


def FSM_SUBSTATE(parent):
    """Declares the decorated class a substate of parent, answering parent's events it does not override."""
    return lambda cls: _state_class(cls, parent)


def deephistory(cls):
    """Entering cls again goes back to the innermost state it was left in."""
    cls._deep_history = True
    return cls


def _state_class(cls, parent):
    # The state inherits its parent's event handlers; its entry, exit and init actions are its own.
    own = {name: value for name, value in cls.__dict__.items() if name in ("onEntry", "onExit", "onInit")}
    bases = (cls,) if parent is None else (cls, parent)
    return type(cls.__name__, bases, {"_own_methods": own, "_parent_state": parent,
                                      "_deep_history": False, "__module__": cls.__module__})


def State(state):
    """The target of a transition: the state class itself."""
    return state


class Event(object):
    """An event: a method of the top state and its arguments."""

    def __init__(self, handler, *args):
        self.handler = handler
        self.args = args

    def __call__(self, state):
        return getattr(state, self.handler.__name__)(*self.args)


class Machine(object):
    """A running machine of top state top: entered at once (its onInit chooses the first substate).
    Events dispatched to it from other threads wait for run_event()."""

    def __init__(self, top, rtobject=None):
        self._top = top
        self._rtobject = rtobject
        self._states = {}
        self._boxes = {}
        self._history = {}
        self._current = None
        self._pending = None
        self._next_events = collections.deque()
        self._events = collections.deque()
        self._lock = threading.Lock()
        self._enter_path(self._path_to(top))
        self._init(top)
        self._run_transitions()

    # --- used by the component ---

    def dispatch(self, event):
        """Queues event until the next run_event() (safe from any thread, as an EventInPort calls it)."""
        with self._lock:
            self._events.append(event)

    def run_event(self):
        """Handles the events that have arrived, in order."""
        while True:
            with self._lock:
                if not self._events:
                    return
                event = self._events.popleft()
            self._handle(event)

    def shutdown(self):
        """Leaves every state, innermost first."""
        if self._current is not None:
            for state in reversed(self._path_to(self._current)):
                self._call_own(state, "onExit")
            self._current = None

    exit = shutdown

    def currentState(self):
        return self._current

    def isInstate(self, state):
        return self._current is not None and issubclass(self._current, state)

    # --- used by the states ---

    def _set_pending(self, state):
        self._pending = state

    def _queue_next(self, event):
        self._next_events.append(event)

    def _box(self, state):
        if state not in self._boxes and hasattr(state, "Data"):
            self._boxes[state] = state.Data()
        return self._boxes.get(state)

    # --- the machine ---

    def _instance(self, state):
        if state not in self._states:
            instance = state()
            instance._machine = self
            self._states[state] = instance
        return self._states[state]

    def _call_own(self, state, action):
        method = _own(state, action)
        return method(self._instance(state)) if method else None

    @staticmethod
    def _path_to(state):
        path = []
        while state is not None:
            path.insert(0, state)
            state = state._parent_state
        return path

    def _enter_path(self, path):
        for state in path:
            self._call_own(state, "onEntry")
        self._current = path[-1]

    def _init(self, state):
        self._call_own(state, "onInit")

    def _handle(self, event):
        event(self._instance(self._current))
        self._run_transitions()
        while self._next_events:
            event = self._next_events.popleft()
            event(self._instance(self._current))
            self._run_transitions()

    def _run_transitions(self):
        while self._pending is not None:
            target, self._pending = self._pending, None
            self._transition(target)

    def _transition(self, target):
        source = self._path_to(self._current)
        destination = self._path_to(target)
        # Left and entered: the states below the last common one; a transition to the current state
        # or one of its parents leaves that state too and enters it again.
        if target in source:
            common = destination.index(target)
        else:
            common = 0
            while common < min(len(source), len(destination)) and source[common] == destination[common]:
                common += 1
        self._remember(source)
        for state in reversed(source[common:]):
            self._call_own(state, "onExit")
        remembered = self._history.get(target) if target._deep_history else None
        if remembered is not None:
            self._enter_path(self._path_to(remembered)[common:])
        else:
            self._enter_path(destination[common:])
            self._init(target)

    def _remember(self, source):
        # Each state with deep history keeps the innermost state left below it.
        for state in source[:-1]:
            if state._deep_history:
                self._history[state] = source[-1]
