// SPDX-License-Identifier: MIT
#pragma once

// The Turnstile fixture (tests/data/sdk/Turnstile.xml, a static FSM driven through an EventPort)
// as a user would finish it: a coin condition, and the current state written to the `state`
// OutPort whenever it changes (0 Locked, 1 Unlocked, 2 Alarm). Shared by the tests that build it
// against the component SDK and against OpenRTM-aist.

#include "rtctlrunner.h"
#include "sdkproject.h"

namespace Turnstile {

inline const SdkTest::UserEdit userEdits[] = {
    {"src/TurnstileFsm.cpp",
     "  bool Top::paidEnough(const RTC::TimedLong& /*data*/)\n  {\n    return true;\n  }",
     "  bool Top::paidEnough(const RTC::TimedLong& data)\n  {\n    // user code: the gate opens for 10 or more\n"
     "    return data.data >= 10;\n  }"},
    {"src/Turnstile.cpp", "  m_fsm.run_event();\n  // </rtc-template>\n  return RTC::RTC_OK;",
     "  m_fsm.run_event();\n  // </rtc-template>\n"
     "  const CORBA::Long state = TurnstileFsm::Alarm::isCurrent(m_fsm) ? 2\n"
     "      : TurnstileFsm::Unlocked::isCurrent(m_fsm) ? 1 : 0;\n"
     "  static CORBA::Long written = -1;\n"
     "  if (state != written)\n"
     "    {\n"
     "      RTC_INFO((\"state %s\", m_fsm.currentState().name()));\n"
     "      m_state.data = state;\n"
     "      setTimestamp(m_state);\n"
     "      m_stateOut.write();\n"
     "      written = state;\n"
     "    }\n"
     "  return RTC::RTC_OK;"},
};

/// Generates the fixture into @p dir with `rtctl gen`, writes the user's code and regenerates
/// around it (the <rtc-template> merge); false with the reason in @p log.
inline bool generate(const QString &dir, QString *log)
{
    const QStringList arguments{"gen", RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdk/Turnstile.xml"), "--lang", "cpp", "-o", dir};
    RtctlResult r = runRtctl(arguments);
    for (const SdkTest::UserEdit &edit : userEdits) {
        if (r.code == 0 && !SdkTest::applyEdit(dir, edit, log))
            return false;
    }
    if (r.code == 0)
        r = runRtctl(arguments + QStringList{"--merge"});
    if (r.code != 0)
        *log = r.out + r.err;
    return r.code == 0;
}

} // namespace Turnstile
