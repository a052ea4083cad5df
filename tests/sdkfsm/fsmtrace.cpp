// SPDX-License-Identifier: MIT
// Prints the lamp scenario's trace (see lampmachine.h), one action a line: built against
// OpenRTM-aist's own Macho, it shows that the SDK's machines behave the same.
#include "lampmachine.h"

#include <iostream>

int main()
{
    for (const std::string &line : Lamp::runLampScenario())
        std::cout << line << '\n';
    return 0;
}
