// SPDX-License-Identifier: MIT
#pragma once

// The SdkGreeter fixture (tests/data/sdk/SdkGreeter) as a user would finish it: the code written
// between the generated blocks (applied with SdkTest::applyEdit). Shared by the
// tests that build the same generated project against the component SDK and against OpenRTM-aist.

#include "sdkproject.h"

namespace SdkGreeter {

/// What the user writes into the generated files (between the generated blocks).
inline const SdkTest::UserEdit userEdits[] = {
    {"src/SdkGreeter.cpp", "#include \"SdkGreeter.h\"\n", "#include \"SdkGreeter.h\"\n\n#include <algorithm>\n"},
    {"src/SdkGreeter.cpp",
     "RTC::ReturnCode_t SdkGreeter::onExecute(RTC::UniqueId /*ec_id*/)\n{\n  return RTC::RTC_OK;\n}",
     "RTC::ReturnCode_t SdkGreeter::onExecute(RTC::UniqueId /*ec_id*/)\n"
     "{\n"
     "  // user code: greet the peer, scale the input within the limits, or report the greetings\n"
     "  if (!CORBA::is_nil(m_peerGreeter._ptr()))\n"
     "    {\n"
     "      try { CORBA::String_var reply = m_peerGreeter->greet(getInstanceName()); }\n"
     "      catch (const CORBA::Exception&) { RTC_WARN((\"peer unreachable\")); }\n"
     "    }\n"
     "  if (m_inIn.isNew())\n"
     "    {\n"
     "      m_inIn.read();\n"
     "      double value = m_in.data * m_gain;\n"
     "      if (m_limits.size() == 2) { value = std::min(std::max(value, m_limits[0]), m_limits[1]); }\n"
     "      m_out.data = static_cast<CORBA::Long>(value);\n"
     "      setTimestamp(m_out);\n"
     "      m_outOut.write();\n"
     "    }\n"
     "  else if (m_greeter.calls() > 0)\n"
     "    {\n"
     "      m_out.data = -m_greeter.calls();\n"
     "      m_outOut.write();\n"
     "    }\n"
     "  return RTC::RTC_OK;\n"
     "}"},
    {"src/GreeterSVC_impl.cpp", "#include \"GreeterSVC_impl.h\"\n",
     "#include \"GreeterSVC_impl.h\"\n\n#include <map>\n#include <mutex>\n#include <string>\n\n"
     "// Greetings received, per servant.\n"
     "static std::mutex greetingsMutex;\n"
     "static std::map<const void*, long> greetings;\n"},
    {"src/GreeterSVC_impl.cpp", "  // TODO: implement greet\n  return CORBA::string_dup(\"\");",
     "  {\n    std::lock_guard<std::mutex> lock(greetingsMutex);\n    ++greetings[this];\n  }\n"
     "  return CORBA::string_dup((std::string(\"hello \") + name).c_str());"},
    {"src/GreeterSVC_impl.cpp", "  // TODO: implement calls\n  return 0;",
     "  std::lock_guard<std::mutex> lock(greetingsMutex);\n  return greetings[this];"},
};

} // namespace SdkGreeter
