// SPDX-License-Identifier: MIT
/*!
 * @file OS.h
 * @brief Thin wrappers of POSIX process and environment calls, and coil::GetOpt.
 *
 * Like OpenRTM-aist's, this header brings <unistd.h>, so component code calling sleep() or
 * usleep() without including it still compiles.
 */
#ifndef COIL_OS_H
#define COIL_OS_H

#include <coil/config_coil.h>

#include <cstdlib>
#include <string>
#include <sys/types.h>
#include <sys/utsname.h>
#include <unistd.h>

namespace coil {
/*! The system identification record. */
typedef ::utsname utsname;
/*! Fills @p name with the system identification; 0 on success. */
inline int uname(utsname *name)
{
    return ::uname(name);
}

/*! A process id. */
typedef ::pid_t pid_t;
/*! This process's id. */
inline pid_t getpid()
{
    return ::getpid();
}
/*! The parent process's id. */
inline pid_t getppid()
{
    return ::getppid();
}

/*! 1.x: the environment variable @p name, or null when unset. */
inline char *getenv(const char *name)
{
    return ::getenv(name);
}
/*! 2.x: stores the environment variable @p name in @p env; false when unset. */
inline bool getenv(const char *name, std::string &env)
{
    const char *value = ::getenv(name);
    if (value == 0)
        return false;
    env = value;
    return true;
}

/*!
 * Command-line option parsing in the style of getopt(3): construct with argc, argv and an
 * option string such as "f:o:d", then call the object until it returns -1. After each call
 * optarg holds the option's argument and optind the index of the next argument.
 */
class GetOpt
{
public:
    /*! Starts parsing @p argv with the options @p opt; @p flag is unused. */
    GetOpt(int argc, char *const argv[], const char *opt, int flag)
        : optarg(0)
        , optind(1)
        , opterr(1)
        , optopt(0)
        , m_argc(argc)
        , m_argv(argv)
        , m_opt(opt)
    {
        (void)flag;
        ::optind = 1;
    }
    ~GetOpt() { ::optind = 1; }
    /*! The next option character, '?' for an unknown one, or -1 at the end. */
    int operator()()
    {
        ::opterr = opterr;
        ::optind = optind;
        const int result = ::getopt(m_argc, m_argv, m_opt);
        optarg = ::optarg;
        optind = ::optind;
        optopt = ::optopt;
        return result;
    }

    /*! The argument of the last option, or null. */
    char *optarg;
    /*! The index of the next element of argv. */
    int optind;
    /*! Set to 0 before a call to silence getopt's error messages. */
    int opterr;
    /*! The option character that caused the last error. */
    int optopt;

private:
    int m_argc;
    char *const *m_argv;
    const char *m_opt;
};
} // namespace coil

#endif // COIL_OS_H
