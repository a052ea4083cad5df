// SPDX-License-Identifier: MIT
/*!
 * @file SharedMemory.h
 * @brief coil::SharedMemory: a named POSIX shared memory segment (shm_open + mmap).
 *
 * One process create()s the segment under a name, others open() it by the same name; both
 * read() and write() at byte offsets. The creator unlink()s the name when the segment is no
 * longer to be found; the memory goes when the last mapping is closed.
 */
#ifndef COIL_SHAREDMEMORY_H
#define COIL_SHAREDMEMORY_H

#include <coil/config_coil.h>

#include <cstdio>
#include <fcntl.h>
#include <string>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

/*! Size of a segment when none is given: 2 MiB. */
#define DEFAULT_MEMORY_SIZE 2097152

namespace coil {
/*! A mapping of a named shared memory segment. Functions return 0 on success, -1 on failure. */
class SharedMemory
{
public:
    SharedMemory();
    /*! Closes the mapping (the name stays until unlink()). */
    virtual ~SharedMemory();
    /*! Maps the same segment again, independently of @p rhs (nothing when @p rhs is not open). */
    SharedMemory(const SharedMemory &rhs);
    SharedMemory &operator=(const SharedMemory &rhs);

    /*!
     * Creates (or reuses) the segment @p shm_address ("name" or "/name") with @p memory_size
     * bytes and maps it. A segment created here is reported by created().
     */
    virtual int create(std::string shm_address, unsigned long long memory_size = DEFAULT_MEMORY_SIZE);
    /*! Maps the existing segment @p shm_address; -1 when there is none. */
    virtual int open(std::string shm_address, unsigned long long memory_size = DEFAULT_MEMORY_SIZE);
    /*! Copies @p size bytes of @p data to offset @p pos; -1 when out of the segment or not open. */
    virtual int write(const char *data, unsigned long long pos, unsigned long long size);
    /*! Copies @p size bytes from offset @p pos to @p data; -1 when out of the segment or not open. */
    virtual int read(char *data, unsigned long long pos, unsigned long long size);
    /*! Unmaps the segment; -1 when nothing was open. */
    virtual int close();
    /*! The mapped size in bytes (0 when not open). */
    virtual unsigned long long get_size();
    /*! The segment's name as given to create() or open(). */
    virtual std::string get_addresss();
    /*! The mapped memory, or null when not open. */
    virtual char *get_data();
    /*! Removes the segment's name; -1 when there is no such segment. */
    virtual int unlink();
    /*! True when this object created the segment. */
    virtual bool created();

private:
    unsigned long long m_memory_size {0};
    std::string m_shm_address;
    char *m_shm {nullptr};
    bool m_file_create {false};
    int m_fd {-1};
};
} // namespace coil

#endif // COIL_SHAREDMEMORY_H
