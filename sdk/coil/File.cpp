// SPDX-License-Identifier: MIT
#include <coil/File.h>

#include <dirent.h>
#include <sys/stat.h>

#include <vector>

namespace coil {
namespace {
// '*' matches any run of characters, '+' a run of at least one; others match themselves.
bool globMatch(const char *name, const char *glob)
{
    if (*glob == '\0')
        return *name == '\0';
    if (*glob == '*' || *glob == '+') {
        const char *start = (*glob == '+') ? name + 1 : name;
        if (*glob == '+' && *name == '\0')
            return false;
        for (const char *rest = start;; ++rest) {
            if (globMatch(rest, glob + 1))
                return true;
            if (*rest == '\0')
                return false;
        }
    }
    return *name == *glob && globMatch(name + 1, glob + 1);
}

// Visits the entries of dir (not "." and "..") and descends into subdirectories.
template<typename Visit> void walk(const std::string &dir, Visit visit, int depth = 0)
{
    if (depth > 64) // guards against symbolic-link cycles
        return;
    DIR *handle = ::opendir(dir.c_str());
    if (handle == nullptr)
        return;
    std::vector<std::string> names;
    while (const dirent *entry = ::readdir(handle))
        names.emplace_back(entry->d_name);
    ::closedir(handle);
    for (const std::string &name : names) {
        if (name == "." || name == "..")
            continue;
        const std::string path = dir + "/" + name;
        struct stat info;
        if (::stat(path.c_str(), &info) != 0)
            continue;
        if (S_ISDIR(info.st_mode))
            walk(path, visit, depth + 1);
        else
            visit(name, path);
    }
}
} // namespace

// dirname(3) and basename(3) without their habit of writing into the argument.
std::string dirname(const char *path)
{
    std::string p(path != nullptr ? path : "");
    const auto lastKept = p.find_last_not_of('/');
    if (lastKept == std::string::npos)
        return p.empty() ? "." : "/";
    const auto slash = p.rfind('/', lastKept);
    if (slash == std::string::npos)
        return ".";
    const auto end = p.find_last_not_of('/', slash);
    return end == std::string::npos ? "/" : p.substr(0, end + 1);
}

std::string basenameOfPath(const char *path)
{
    std::string p(path != nullptr ? path : "");
    const auto lastKept = p.find_last_not_of('/');
    if (lastKept == std::string::npos)
        return p.empty() ? "." : "/";
    const auto slash = p.rfind('/', lastKept);
    return p.substr(slash == std::string::npos ? 0 : slash + 1,
                    slash == std::string::npos ? lastKept + 1 : lastKept - slash);
}

coil::vstring filelist(const char *path, const char *glob_str)
{
    coil::vstring names;
    if (path == nullptr)
        return names;
    DIR *handle = ::opendir(path);
    if (handle == nullptr)
        return names;
    const bool filter = glob_str != nullptr && glob_str[0] != '\0';
    while (const dirent *entry = ::readdir(handle))
        if (!filter || globMatch(entry->d_name, glob_str))
            names.emplace_back(entry->d_name);
    ::closedir(handle);
    return names;
}

void findFile(const std::string &dir, const std::string &filename, coil::vstring &filelist)
{
    walk(dir, [&](const std::string &name, const std::string &path) {
        if (name == filename)
            filelist.push_back(path);
    });
}

void getFileList(const std::string &dir, const std::string &ext, coil::vstring &filelist)
{
    walk(dir, [&](const std::string &name, const std::string &path) {
        const auto dot = name.rfind('.');
        const std::string last = dot == std::string::npos ? name : name.substr(dot + 1);
        if (last == ext)
            filelist.push_back(path);
    });
}
} // namespace coil
