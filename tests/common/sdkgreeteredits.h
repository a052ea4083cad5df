// SPDX-License-Identifier: MIT
#pragma once

// The SdkGreeter fixture (tests/data/sdk/SdkGreeter) as a user would finish it: the code written
// between the generated blocks, and the tools that apply it and build the project. Shared by the
// tests that build the same generated project against the component SDK and against OpenRTM-aist.

#include <QByteArray>
#include <QFile>
#include <QString>
#include <QStringList>

namespace SdkGreeter {

/// What the user writes into the generated files (between the generated blocks).
struct UserEdit
{
    const char *file;
    const char *before;
    const char *after;
};

inline const UserEdit userEdits[] = {
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
    {"src/GreeterSVC_impl.cpp", "  // Please insert your code here.\n  return CORBA::string_dup(\"\");",
     "  {\n    std::lock_guard<std::mutex> lock(greetingsMutex);\n    ++greetings[this];\n  }\n"
     "  return CORBA::string_dup((std::string(\"hello \") + name).c_str());"},
    {"src/GreeterSVC_impl.cpp", "  // Please insert your code here.\n  return 0;",
     "  std::lock_guard<std::mutex> lock(greetingsMutex);\n  return greetings[this];"},
};

/// Replaces the first generated text of @p edit in the project at @p root with the user's text.
inline bool applyEdit(const QString &root, const UserEdit &edit, QString *error)
{
    QFile file(root + '/' + edit.file);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = "cannot read " + file.fileName();
        return false;
    }
    QByteArray text = file.readAll();
    file.close();
    if (!text.contains(edit.before)) {
        *error = QString("%1 has no '%2'").arg(edit.file, edit.before);
        return false;
    }
    text.replace(edit.before, edit.after);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(text) != text.size()) {
        *error = "cannot write " + file.fileName();
        return false;
    }
    return true;
}

} // namespace SdkGreeter
