// SPDX-License-Identifier: MIT
/*!
 * @file File.h
 * @brief File name helpers and directory listings.
 */
#ifndef COIL_FILE_H
#define COIL_FILE_H

#include <coil/config_coil.h>
#include <coil/stringutil.h>

#include <libgen.h> // may define basename as a macro: coil::basename below follows it
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <string>
#include <sys/stat.h>
#include <sys/types.h>

namespace coil {
/*! The last part of @p path (implementation of coil::basename). */
std::string basenameOfPath(const char *path);

/*! The directory part of @p path, as dirname(3): "/a/b" gives "/a", "b" gives ".". */
std::string dirname(const char *path);
/*! The last part of @p path, as basename(3): "/a/b.so" gives "b.so". */
inline std::string basename(const char *path)
{
    return basenameOfPath(path);
}
/*!
 * The names in directory @p path (including "." and ".."), or only those matching
 * @p glob_str, where '*' stands for any characters and '+' for at least one.
 */
coil::vstring filelist(const char *path, const char *glob_str = "");
/*! Appends the paths of all files named @p filename below @p dir (recursively). */
void findFile(const std::string &dir, const std::string &filename, coil::vstring &filelist);
/*! Appends the paths of all files below @p dir whose extension is @p ext (no dot). */
void getFileList(const std::string &dir, const std::string &ext, coil::vstring &filelist);
} // namespace coil

#endif // COIL_FILE_H
