// SPDX-License-Identifier: MIT
// A marshalled sample, as connector data listeners of the untyped kind receive it.
#ifndef RTM_BYTEDATA_H
#define RTM_BYTEDATA_H

#include <cstdint>
#include <cstring>
#include <vector>

namespace RTC
{
/// Bytes of one CDR-encoded sample.
class ByteData
{
public:
    ByteData() = default;
    ByteData(const unsigned char *data, unsigned long length) : m_data(data, data + length) {}

    unsigned char *getBuffer() { return m_data.data(); }
    const unsigned char *getBuffer() const { return m_data.data(); }
    unsigned long getDataLength() const { return static_cast<unsigned long>(m_data.size()); }
    void setDataLength(unsigned long length) { m_data.resize(length); }
    /// Replaces the contents with a copy of @p length bytes at @p data.
    void writeData(const unsigned char *data, unsigned long length) { m_data.assign(data, data + length); }
    /// Copies up to @p length bytes into @p data.
    void readData(unsigned char *data, unsigned long length) const
    {
        std::memcpy(data, m_data.data(), length < m_data.size() ? length : m_data.size());
    }
    bool empty() const { return m_data.empty(); }

private:
    std::vector<unsigned char> m_data;
};
} // namespace RTC

#endif // RTM_BYTEDATA_H
