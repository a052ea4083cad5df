// SPDX-License-Identifier: MIT
// Samples as rtctl print, rtctl log and the Port Monitor decode them (Codegen::CdrCodec over
// OpenRTM's IDL), and values as rtctl inject reads them from a command line.
//
// Input: one byte choosing the data type (bits 1…) and the byte order (bit 0), then the sample.
// A sample that decodes must encode again to bytes that decode to the same value; the rest of
// the input, read as a command-line value, must be parsed or refused, never crash.

#include "cdrcodec.h"
#include "idltypelibrary.h"

#include <cstdint>
#include <cstdlib>

namespace {

const Codegen::IdlModel &model()
{
    static const Codegen::IdlTypeLibrary library({RTSTUDIO_IDL_DIR});
    return library.model();
}

const QStringList &types()
{
    static const QStringList names = [] {
        QStringList all = model().structs.keys() + model().unions.keys() + model().enums.keys();
        all.sort();
        return all;
    }();
    return names;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || types().isEmpty())
        return 0;
    const QString type = types().at(int((data[0] >> 1) % unsigned(types().size())));
    const bool little = data[0] & 1;
    const QByteArray sample = QByteArray::fromRawData(reinterpret_cast<const char *>(data + 1), qsizetype(size - 1));
    const Codegen::CdrCodec codec(model());
    QString error;
    const QJsonValue value = codec.decode(type, sample, little, &error);
    if (error.isEmpty()) {
        codec.toText(type, value);
        codec.toJson(type, value);
        const QByteArray again = codec.encode(type, value, little, &error);
        if (!error.isEmpty() || codec.decode(type, again, little, &error) != value)
            std::abort(); // what we decoded must survive our own encoding
    }
    error.clear();
    const QJsonValue argument = codec.parseArgument(type, QString::fromUtf8(sample), &error);
    if (error.isEmpty())
        codec.encode(type, argument, little, &error);
    return 0;
}
