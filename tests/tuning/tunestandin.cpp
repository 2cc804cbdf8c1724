// The same runTune() that slew's main() hands `--tune` to, in a program of
// its own, so `slew --tune` is tested as a process even in a build whose
// slew binary does not route --tune yet (tst_slewtune prefers SLEW_BIN when it does).
#include "slew_tune.h"

int main(int argc, char **argv)
{
    return runTune(argc, argv);
}
