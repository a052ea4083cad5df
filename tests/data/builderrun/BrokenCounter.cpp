// A source file a compiler complained about: the Problems panel's viewer shows it at line 14.
#include <cstdio>

namespace {

int counted = 0;

} // namespace

int count(int step)
{
    counted += step;
    // The next line is the one the test's diagnostic points at.
    return counted + undeclaredValue;
}

int main()
{
    std::printf("%d\n", count(1));
    return 0;
}
