// SPDX-License-Identifier: MIT
#include <coil/SharedMemory.h>

#include <cerrno>
#include <cstring>

namespace coil {
namespace {
// shm_open wants one leading slash and no other.
std::string shmName(const std::string &address)
{
    return !address.empty() && address[0] == '/' ? address : "/" + address;
}

char *mapSegment(int fd, unsigned long long size)
{
    void *memory = ::mmap(nullptr, static_cast<size_t>(size), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    return memory == MAP_FAILED ? nullptr : static_cast<char *>(memory);
}
} // namespace

SharedMemory::SharedMemory() = default;

SharedMemory::~SharedMemory()
{
    close();
}

SharedMemory::SharedMemory(const SharedMemory &rhs)
{
    if (rhs.m_shm != nullptr)
        open(rhs.m_shm_address, rhs.m_memory_size);
}

SharedMemory &SharedMemory::operator=(const SharedMemory &rhs)
{
    if (this == &rhs)
        return *this;
    close();
    if (rhs.m_shm != nullptr)
        open(rhs.m_shm_address, rhs.m_memory_size);
    return *this;
}

int SharedMemory::create(std::string shm_address, unsigned long long memory_size)
{
    if (shm_address.empty() || memory_size == 0)
        return -1;
    close();
    const std::string name = shmName(shm_address);
    // Exclusive first, to know whether this object made the segment.
    int fd = ::shm_open(name.c_str(), O_RDWR | O_CREAT | O_EXCL, 0666);
    bool made = fd >= 0;
    if (!made && errno == EEXIST)
        fd = ::shm_open(name.c_str(), O_RDWR, 0666);
    if (fd < 0)
        return -1;
    if (::ftruncate(fd, static_cast<off_t>(memory_size)) != 0) {
        ::close(fd);
        if (made)
            ::shm_unlink(name.c_str());
        return -1;
    }
    char *memory = mapSegment(fd, memory_size);
    if (memory == nullptr) {
        ::close(fd);
        if (made)
            ::shm_unlink(name.c_str());
        return -1;
    }
    m_fd = fd;
    m_shm = memory;
    m_memory_size = memory_size;
    m_shm_address = shm_address;
    m_file_create = made;
    return 0;
}

int SharedMemory::open(std::string shm_address, unsigned long long memory_size)
{
    if (shm_address.empty() || memory_size == 0)
        return -1;
    close();
    const int fd = ::shm_open(shmName(shm_address).c_str(), O_RDWR, 0666);
    if (fd < 0)
        return -1;
    // Mapping beyond the segment's end would fault on access: never map more than it has.
    struct stat info;
    if (::fstat(fd, &info) != 0 || static_cast<unsigned long long>(info.st_size) < memory_size) {
        ::close(fd);
        return -1;
    }
    char *memory = mapSegment(fd, memory_size);
    if (memory == nullptr) {
        ::close(fd);
        return -1;
    }
    m_fd = fd;
    m_shm = memory;
    m_memory_size = memory_size;
    m_shm_address = shm_address;
    m_file_create = false;
    return 0;
}

int SharedMemory::write(const char *data, unsigned long long pos, unsigned long long size)
{
    if (m_shm == nullptr || data == nullptr || pos > m_memory_size || size > m_memory_size - pos)
        return -1;
    std::memcpy(m_shm + pos, data, static_cast<size_t>(size));
    return 0;
}

int SharedMemory::read(char *data, unsigned long long pos, unsigned long long size)
{
    if (m_shm == nullptr || data == nullptr || pos > m_memory_size || size > m_memory_size - pos)
        return -1;
    std::memcpy(data, m_shm + pos, static_cast<size_t>(size));
    return 0;
}

int SharedMemory::close()
{
    if (m_shm == nullptr)
        return -1;
    ::munmap(m_shm, static_cast<size_t>(m_memory_size));
    ::close(m_fd);
    m_shm = nullptr;
    m_fd = -1;
    m_memory_size = 0;
    return 0;
}

unsigned long long SharedMemory::get_size()
{
    return m_memory_size;
}

std::string SharedMemory::get_addresss()
{
    return m_shm_address;
}

char *SharedMemory::get_data()
{
    return m_shm;
}

int SharedMemory::unlink()
{
    if (m_shm_address.empty())
        return -1;
    return ::shm_unlink(shmName(m_shm_address).c_str()) == 0 ? 0 : -1;
}

bool SharedMemory::created()
{
    return m_file_create;
}
} // namespace coil
