// The Build tests expect the warning on line 5 and the error on line 6.

int main()
{
    int unused;
    return undeclaredName;
}
