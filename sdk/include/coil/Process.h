// SPDX-License-Identifier: MIT
/*!
 * @file Process.h
 * @brief Starting other programs.
 */
#ifndef COIL_PROCESS_H
#define COIL_PROCESS_H

#include <coil/config_coil.h>
#include <coil/stringutil.h>

#include <cstdlib>
#include <libgen.h>
#include <string>
#include <unistd.h>
#include <vector>

namespace coil {
/*!
 * Starts @p command (a program and its arguments, split at blanks; quotes group words) in
 * the background, detached from this process. Returns 0 when it could be started from
 * here, -1 otherwise (a program that does not exist is only noticed by the child).
 */
int launch_shell(const std::string &command);
/*! Detaches this process from its terminal, as daemon(3). */
int daemon(int nochdir, int noclose);
/*!
 * Runs @p command through the shell and stores its standard output in @p out, one string
 * per line. Returns 0, or -1 when the command could not be started.
 */
int create_process(const std::string &command, std::vector<std::string> &out);
} // namespace coil

#endif // COIL_PROCESS_H
