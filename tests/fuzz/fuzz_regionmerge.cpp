// SPDX-License-Identifier: MIT
// The `<rtc-template>` region merge of regenerated files into the user's edited ones.
//
// Input: the user's file, a NUL byte, the fresh file. Without a NUL the input is merged with
// itself, which must give it back unchanged whenever its markers are sound.

#include "regionmerge.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *text = reinterpret_cast<const char *>(data);
    const void *nul = size > 0 ? std::memchr(text, 0, size) : nullptr;
    const size_t split = nul ? size_t(static_cast<const char *>(nul) - text) : size;
    const QString existing = QString::fromUtf8(text, qsizetype(split));
    const QString fresh = nul ? QString::fromUtf8(text + split + 1, qsizetype(size - split - 1)) : existing;
    Codegen::templateRegionNames(existing);
    Codegen::templateRegionNames(fresh);
    const Codegen::RegionMergeResult result = Codegen::mergeTemplateRegions(existing, fresh);
    if (!nul && result.text && *result.text != existing)
        std::abort();
    return 0;
}
