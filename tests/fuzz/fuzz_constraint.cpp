// SPDX-License-Identifier: MIT
// The constraint syntax of RTC Builder's configuration editor (`0<=x<=100`, `(a,b)`, `{k: 1}` …).
// Whatever parses must write back to a string that parses to the same tree, as the header says.

#include "constraintsyntax.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QString text = QString::fromUtf8(reinterpret_cast<const char *>(data), qsizetype(size));
    const Profile::ConstraintParseResult result = Profile::parseConstraintString(text);
    if (!result.ok()) {
        result.error->toString();
        return 0;
    }
    if (result.constraint)
        Profile::isEnumerationConstraint(*result.constraint);
    const Profile::ConstraintParseResult again =
        Profile::parseConstraintString(Profile::constraintToString(result.constraint));
    if (!again.ok() || !(again.constraint == result.constraint))
        std::abort();
    return 0;
}
