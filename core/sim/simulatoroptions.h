#pragma once
// Everything that can be set when a simulator starts: the plant, the gains,
// the faults, the dialect and the line. The same names serve the `sim:` URI
// query items (`sim:?kp=30&az_max=450&jam=az`) and slew-sim's flags
// (`--kp 30 --az-max 450 --jam az`), so one parser handles both.

#include "axisparameters.h"
#include "linkfaults.h"
#include "simulatedrotator.h"

#include "protocol/dialect.h"
#include "protocol/firmware.h"

#include <QString>
#include <QStringView>

#include <vector>

namespace slew::sim {

// Whose firmware answers: Slew's own reading of the protocol documents
// (Generic), or the way one that stations run answers (docs/protocol.md,
// "Controllers in the field"): K3NG's Arduino firmware in its Easycom
// (easycomm2) or Yaesu (gs232a, gs232b) emulation, the SatNOGS firmware.
using protocol::Firmware;

struct SimulatorOptions {
    RotatorConfig rotator;
    AxisFaults azimuthFaults;
    AxisFaults elevationFaults;
    LinkFaults link;
    protocol::Dialect dialect = protocol::Dialect::Easycomm3;
    bool unsolicited = false; // push changed fields as the Easycomm III derivative's controller does
    bool echo = false;        // send every received byte back first, as some serial adapters do
    bool checksum = false;    // every line `*HH`-framed both ways (docs/protocol.md, "Checksum")
    int baud = 0;             // 0: bytes move as fast as the link carries them
    bool manualClock = false; // time moves only when advanced (tests)
    double timeScale = 1.0;   // wall clock: simulated seconds per real second
    QString stateFile;        // micro2g: where calibration, presets and tolerances are kept; empty: lost at exit
    int spidPulses = 2;       // rot2prog, md01: pulses per degree reported in PH/PV (1, 2, 4, 10)
    bool md01Log = false;     // md01: a text log line before every reply, as some MD-01 firmware writes
    Firmware firmware = Firmware::Generic;
};

struct SimulatorOptionInfo {
    const char *name;        // URI item; the flag is the same with '-' for '_'
    const char *valueName;   // empty: a switch (`--unsolicited`, `unsolicited=1`)
    const char *description;
};

// Every option, for --help and for the URI documentation.
const std::vector<SimulatorOptionInfo> &simulatorOptionList();

// Applies one option. Accepts '-' or '_' in the name. Returns an empty
// string on success, else a message naming the option and what is wrong.
QString applySimulatorOption(SimulatorOptions &options, QStringView name, QStringView value);

// What no single option can say: options that do not go together (a
// firmware with a dialect it has no emulation of). Empty when they do.
QString checkSimulatorOptions(const SimulatorOptions &options);

} // namespace slew::sim
