// SPDX-License-Identifier: MIT
// The FSM listener holders and FsmActionListeners.
#include <rtm/FsmActionListener.h>

#include "listenerarrays.h"

namespace RTC {

using Sdk::addTo;
using Sdk::nameOf;
using Sdk::notifyIn;
using Sdk::removeFrom;

const char *FsmProfileListener::toString(FsmProfileListenerType type)
{
    static const char *const names[] = {"SET_FSM_PROFILE",       "GET_FSM_PROFILE",       "ADD_FSM_STATE",
                                        "REMOVE_FSM_STATE",      "ADD_FSM_TRANSITION",    "REMOVE_FSM_TRANSITION",
                                        "BIND_FSM_EVENT",        "UNBIND_FSM_EVENT",      "FSM_PROFILE_LISTENER_NUM"};
    return nameOf(type, names);
}
FsmProfileListener::~FsmProfileListener() = default;

const char *FsmStructureListener::toString(FsmStructureListenerType type)
{
    static const char *const names[] = {"SET_FSM_STRUCTURE", "GET_FSM_STRUCTURE", "FSM_STRUCTURE_LISTENER_NUM"};
    return nameOf(type, names);
}
FsmStructureListener::~FsmStructureListener() = default;

PreFsmActionListenerHolder::PreFsmActionListenerHolder() = default;
PreFsmActionListenerHolder::~PreFsmActionListenerHolder() = default;
void PreFsmActionListenerHolder::notify(const char *state)
{
    LISTENERHOLDER_CALLBACK(operator(), (state));
}

PostFsmActionListenerHolder::PostFsmActionListenerHolder() = default;
PostFsmActionListenerHolder::~PostFsmActionListenerHolder() = default;
void PostFsmActionListenerHolder::notify(const char *state, ReturnCode_t ret)
{
    LISTENERHOLDER_CALLBACK(operator(), (state, ret));
}

FsmProfileListenerHolder::FsmProfileListenerHolder() = default;
FsmProfileListenerHolder::~FsmProfileListenerHolder() = default;
void FsmProfileListenerHolder::notify(RTC::FsmProfile &profile)
{
    LISTENERHOLDER_CALLBACK(operator(), (profile));
}

FsmStructureListenerHolder::FsmStructureListenerHolder() = default;
FsmStructureListenerHolder::~FsmStructureListenerHolder() = default;
void FsmStructureListenerHolder::notify(RTC::FsmStructure &structure)
{
    LISTENERHOLDER_CALLBACK(operator(), (structure));
}

FsmActionListeners::FsmActionListeners() = default;
FsmActionListeners::~FsmActionListeners() = default;

bool FsmActionListeners::addListener(PreFsmActionListenerType type, PreFsmActionListener *listener, bool autoclean)
{
    return addTo(preaction_, type, listener, autoclean);
}

bool FsmActionListeners::removeListener(PreFsmActionListenerType type, PreFsmActionListener *listener)
{
    return removeFrom(preaction_, type, listener);
}

bool FsmActionListeners::addListener(PostFsmActionListenerType type, PostFsmActionListener *listener, bool autoclean)
{
    return addTo(postaction_, type, listener, autoclean);
}

bool FsmActionListeners::removeListener(PostFsmActionListenerType type, PostFsmActionListener *listener)
{
    return removeFrom(postaction_, type, listener);
}

bool FsmActionListeners::addListener(FsmProfileListenerType type, FsmProfileListener *listener, bool autoclean)
{
    return addTo(profile_, type, listener, autoclean);
}

bool FsmActionListeners::removeListener(FsmProfileListenerType type, FsmProfileListener *listener)
{
    return removeFrom(profile_, type, listener);
}

bool FsmActionListeners::addListener(FsmStructureListenerType type, FsmStructureListener *listener, bool autoclean)
{
    return addTo(structure_, type, listener, autoclean);
}

bool FsmActionListeners::removeListener(FsmStructureListenerType type, FsmStructureListener *listener)
{
    return removeFrom(structure_, type, listener);
}

bool FsmActionListeners::notify(PreFsmActionListenerType type, const char *state)
{
    return notifyIn(preaction_, type, state);
}

bool FsmActionListeners::notify(PostFsmActionListenerType type, const char *state, ReturnCode_t ret)
{
    return notifyIn(postaction_, type, state, ret);
}

bool FsmActionListeners::notify(FsmProfileListenerType type, RTC::FsmProfile &profile)
{
    return notifyIn(profile_, type, profile);
}

bool FsmActionListeners::notify(FsmStructureListenerType type, RTC::FsmStructure &structure)
{
    return notifyIn(structure_, type, structure);
}

} // namespace RTC
