// SPDX-License-Identifier: MIT
// Includes coil by the versioned folders and by 1.x names, and HRTM's headers; prints what they did.
#include <coil-2.0/coil/Timer.h>
#include <coil-2.1/coil/Properties.h>
#include <coil/Time.h>
#include <coil/TimeValue.h>
#include <hrtm/properties.h>
#include <hrtm/version.h>
#include <rtm/config_rtc.h>

#include <chrono>
#include <iostream>

int main()
{
    int ticks = 0;
    coil::Timer<coil::PeriodicFunction> timer;
    timer.emplace([&ticks] { ++ticks; }, std::chrono::milliseconds(10));
    for (int i = 0; i < 3; ++i)
        timer.tick(std::chrono::milliseconds(10));

    static const char *const spec[] = {"key", "value", ""};
    hrtm::utils::Properties properties(spec);
    coil::TimeValue interval(1.5);
    std::cout << "olderpaths " << RTM_VERSION << " ticks=" << ticks << " key=" << properties.getProperty("key")
              << " " << double(interval) << " hrtm=" << HRTM_VERSION_MAJOR << '.' << HRTM_VERSION_MINOR << '.'
              << HRTM_VERSION_PATCH << std::endl;
    return 0;
}
