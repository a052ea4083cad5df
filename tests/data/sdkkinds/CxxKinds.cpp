// SPDX-License-Identifier: MIT
// CxxKinds: provides PyKinds::Echo on its service port "Provided" (as tests/data/pythonidl's
// PyKindsProvider.py answers) and, once its port "Required" is connected and it is active, calls
// the Echo there once with wide characters, a union, anys and its own servant's reference, printing
// what came back (UTF-8) and "cxx consumer: done".
#include "Kinds.hh"

#include <rtm/CorbaConsumer.h>
#include <rtm/CorbaPort.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/Manager.h>

#include <clocale>
#include <cwctype>
#include <functional>
#include <iostream>
#include <string>

namespace {

std::string utf8(const std::wstring &text)
{
    std::string out;
    for (const wchar_t c : text) {
        const auto code = static_cast<unsigned long>(c);
        if (code < 0x80) {
            out += char(code);
        } else if (code < 0x800) {
            out += char(0xC0 | (code >> 6));
            out += char(0x80 | (code & 0x3F));
        } else {
            out += char(0xE0 | (code >> 12));
            out += char(0x80 | ((code >> 6) & 0x3F));
            out += char(0x80 | (code & 0x3F));
        }
    }
    return out;
}

/// Prints @p line whole: the provider's and the consumer's lines come from different threads.
void printLine(const std::string &line)
{
    std::cout << (line + '\n') << std::flush;
}

std::string describe(const PyKinds::Pick &pick)
{
    switch (pick._d()) {
    case 1:
        return "number " + std::to_string(pick.number());
    case 2:
        return std::string("text ") + pick.text();
    default:
        return "other " + std::to_string(pick.other());
    }
}

class Echo : public virtual POA_PyKinds::Echo
{
public:
    CORBA::WChar letter(CORBA::WChar c, CORBA::WString_out repeated) override
    {
        ++m_calls;
        repeated = CORBA::wstring_dup(std::wstring(3, wchar_t(c)).c_str());
        return CORBA::WChar(std::towupper(wint_t(c)));
    }
    CORBA::WChar *reversed(const CORBA::WChar *w) override
    {
        ++m_calls;
        std::wstring text(w);
        return CORBA::wstring_dup(std::wstring(text.rbegin(), text.rend()).c_str());
    }
    PyKinds::Pick *swap(const PyKinds::Pick &p, PyKinds::Pick &q) override
    {
        ++m_calls;
        auto *result = new PyKinds::Pick(q);
        q = p;
        return result;
    }
    PyKinds::Echo_ptr relay(PyKinds::Echo_ptr other, PyKinds::Echo_out self) override
    {
        ++m_calls;
        printLine("cxx provider: relay of a reference that answers calls() "
                  + (CORBA::is_nil(other) ? std::string("None") : std::to_string(other->calls())));
        self = _this();
        return PyKinds::Echo::_duplicate(other);
    }
    CORBA::Any *wrap(const CORBA::Any &value, CORBA::Any_out described) override
    {
        ++m_calls;
        described = new CORBA::Any;
        CORBA::Double number = 0;
        const char *text = nullptr;
        CORBA::UShort small = 0;
        if (value >>= number)
            *described <<= ("double " + std::to_string(number)).c_str();
        else if (value >>= text)
            *described <<= (std::string("string ") + text).c_str();
        else if (value >>= small)
            *described <<= ("unsigned short " + std::to_string(small)).c_str();
        else
            *described <<= describeConstructed(value).c_str();
        return new CORBA::Any(value);
    }
    CORBA::Long calls() override { return m_calls; }

private:
    /// An any of a union, a struct, a TypeCode or a sequence, as text ("" for other types).
    static std::string describeConstructed(const CORBA::Any &value)
    {
        const PyKinds::Pick *pick = nullptr;
        const RTC::Time *time = nullptr;
        CORBA::TypeCode_ptr type = CORBA::TypeCode::_nil();
        const CORBA::LongSeq *numbers = nullptr;
        if (value >>= pick)
            return "Pick " + describe(*pick);
        if (value >>= time)
            return "RTC::Time " + std::to_string(time->sec) + ' ' + std::to_string(time->nsec);
        if (value >>= type)
            return std::string("TypeCode ") + type->id();
        if (value >>= numbers) {
            std::string text = "sequence";
            for (CORBA::ULong i = 0; i < numbers->length(); ++i)
                text += ' ' + std::to_string((*numbers)[i]);
            return text;
        }
        return {};
    }

    CORBA::Long m_calls = 0;
};

/// A servant of this process, passed to the peer as a reference to call back.
class LocalEcho : public Echo
{
public:
    CORBA::Long calls() override { return 7; }
};

class CxxKinds : public RTC::DataFlowComponentBase
{
public:
    explicit CxxKinds(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_providedPort("Provided")
        , m_requiredPort("Required")
    { }

    RTC::ReturnCode_t onInitialize() override
    {
        m_providedPort.registerProvider("echo", "Echo", m_echo);
        m_requiredPort.registerConsumer("echo", "Echo", m_peer);
        addPort(m_providedPort);
        addPort(m_requiredPort);
        return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        if (m_done || CORBA::is_nil(m_peer._ptr()))
            return RTC::RTC_OK;
        m_done = true;
        try {
            callPeer();
        } catch (const CORBA::Exception &error) {
            printLine(std::string("cxx consumer: ") + error._name());
        }
        printLine("cxx consumer: done");
        return RTC::RTC_OK;
    }

private:
    void callPeer()
    {
        CORBA::WString_var repeated;
        const CORBA::WChar upper = m_peer->letter(L'\u00e9', repeated.out());
        printLine("cxx consumer: letter " + utf8(std::wstring(1, wchar_t(upper))) + ' ' + utf8(repeated.in()));
        CORBA::WString_var reversed = m_peer->reversed(L"h\u00e9llo \u4e16");
        printLine("cxx consumer: reversed " + utf8(reversed.in()));
        PyKinds::Pick p, q;
        p.number(5);
        q.text("t");
        PyKinds::Pick_var result = m_peer->swap(p, q);
        printLine("cxx consumer: swap " + describe(result.in()) + ", " + describe(q));
        CORBA::Any value;
        value <<= CORBA::Long(-12);
        CORBA::Any_var described;
        CORBA::Any_var same = m_peer->wrap(value, described.out());
        CORBA::Long back = 0;
        const char *text = nullptr;
        if ((same.in() >>= back) && (described.in() >>= text))
            printLine("cxx consumer: wrap " + std::to_string(back) + ' ' + text);
        wrapConstructed();
        PyKinds::Echo_var local = m_local._this();
        PyKinds::Echo_var self;
        PyKinds::Echo_var relayed = m_peer->relay(local.in(), self.out());
        printLine("cxx consumer: relay " + std::to_string(relayed->calls()) + ' '
                  + (self->calls() >= 4 ? "True" : "False"));
    }

    /// Anys of a struct, a union and a TypeCode to the peer, printing what it made of them.
    void wrapConstructed()
    {
        PyKinds::Pick pick;
        pick.text("t");
        const std::function<void(CORBA::Any &)> fills[] = {
            [](CORBA::Any &value) { value <<= RTC::Time{1, 2}; },
            [&pick](CORBA::Any &value) { value <<= pick; },
            [](CORBA::Any &value) { value <<= PyKinds::_tc_Pick; },
        };
        for (const auto &fill : fills) {
            CORBA::Any value;
            fill(value);
            CORBA::Any_var described;
            CORBA::Any_var same = m_peer->wrap(value, described.out());
            const char *text = nullptr;
            if ((described.in() >>= text) && same->type()->equal(value.type()))
                printLine(std::string("cxx consumer: wrap ") + text);
        }
    }

    RTC::CorbaPort m_providedPort;
    RTC::CorbaPort m_requiredPort;
    Echo m_echo;
    LocalEcho m_local;
    RTC::CorbaConsumer<PyKinds::Echo> m_peer;
    bool m_done = false;
};

const char *const spec[] = {"implementation_id", "CxxKinds", "type_name", "CxxKinds", "description",
                            "PyKinds::Echo both ways", "version", "1.0", "vendor", "RT Studio tests",
                            "category", "test", "activity_type", "DataFlowComponent", "max_instance", "1",
                            "language", "C++", "lang_type", "compile", ""};

void init(RTC::Manager *manager)
{
    coil::Properties profile(spec);
    manager->registerFactory(profile, RTC::Create<CxxKinds>, RTC::Delete<CxxKinds>);
    manager->createComponent("CxxKinds");
}

} // namespace

int main(int argc, char **argv)
{
    // Wide characters change case by their Unicode properties.
    std::setlocale(LC_CTYPE, "C.UTF-8");
    RTC::Manager *manager = RTC::Manager::init(argc, argv);
    manager->setModuleInitProc(init);
    manager->activateManager();
    manager->runManager();
    return 0;
}
