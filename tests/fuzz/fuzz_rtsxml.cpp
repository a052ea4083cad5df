// SPDX-License-Identifier: MIT
// RTS Profile XML reader (RT System Editor, rtsprofile), then what is done with a profile that was
// read: validation, and saving as XML and YAML, which must read back.

#include "rtsvalidator.h"
#include "rtsxml.h"
#include "rtsyaml.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray text = QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size));
    Profile::Diagnostics diagnostics;
    const std::optional<Profile::RtsProfile> profile =
        Profile::readRtsXml(text, QStringLiteral("fuzz.xml"), &diagnostics);
    if (!profile)
        return 0;
    Profile::validateRtsProfile(*profile, QStringLiteral("fuzz.xml"));
    Profile::Diagnostics again;
    if (!Profile::readRtsXml(Profile::writeRtsXml(*profile), QStringLiteral("saved.xml"), &again))
        std::abort(); // a profile we read must survive our own save
    Profile::readRtsYaml(Profile::writeRtsYaml(*profile), QStringLiteral("saved.yaml"), &again);
    return 0;
}
