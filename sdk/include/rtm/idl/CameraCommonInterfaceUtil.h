// SPDX-License-Identifier: MIT
// copyData() for the camera interface's image types, whose pixels are a large octet sequence.
#ifndef RTC_CAMERACOMMONINTERFACEUTIL_H
#define RTC_CAMERACOMMONINTERFACEUTIL_H

#include "CameraCommonInterfaceSkel.h"
#include <rtm/DataTypeUtil.h>

namespace CORBA_Util
{
/// Copies the image's size and format and its pixels in one block.
template <>
void copyData(Img::ImageData &data1, const Img::ImageData &data2);
/// Copies the image (see above), its capture time and its camera parameters.
template <>
void copyData(Img::CameraImage &data1, const Img::CameraImage &data2);
/// Copies the time stamp, the image (see above) and the error code.
template <>
void copyData(Img::TimedCameraImage &data1, const Img::TimedCameraImage &data2);
} // namespace CORBA_Util

#endif // RTC_CAMERACOMMONINTERFACEUTIL_H
