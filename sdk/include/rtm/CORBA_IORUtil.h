// SPDX-License-Identifier: MIT
// Stringified object references ("IOR:…") taken apart and put together with omniORB's IOP types:
// decode and encode, list the IIOP endpoints, move a reference to another host, print its content.
#ifndef CORBA_IORUTIL_H
#define CORBA_IORUTIL_H

#include <rtm/RTC.h>

#include <omniORB4/IIOP.h>

#include <string>
#include <vector>

namespace CORBA_IORUtil
{
/// Decodes "IOR:<hex>" into `ior`; false when it is no well-formed IOR.
bool toIOR(const char *iorstr, IOP::IOR &ior);
/// Encodes `ior` as "IOR:<hex>" into `iorstr` (big-endian, as omniORB writes them).
bool toString(IOP::IOR &ior, std::string &iorstr);
/// Makes every IIOP profile of the reference `iorstr` point at host `endpoint` (the port stays);
/// false when `iorstr` is no IOR.
bool replaceEndpoint(std::string &iorstr, const std::string &endpoint);
/// A readable account of the reference: type id, each profile's version, address, object key
/// and tagged components.
std::string formatIORinfo(const char *iorstr);
/// Every IIOP address of the reference: each profile's own and its alternate addresses.
std::vector<IIOP::Address> getEndpoints(IOP::IOR &ior);
/// Appends the alternate IIOP addresses (TAG_ALTERNATE_IIOP_ADDRESS) found in `comp` to `addr`.
void extractAddrs(IOP::MultipleComponentProfile &comp, std::vector<IIOP::Address> &addr);
} // namespace CORBA_IORUtil

#endif // CORBA_IORUTIL_H
