#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Writes a fresh Gpredict 2.3 configuration for the Doppler comparison in
# docs/radio.md ("Against the real Gpredict"): the station JO65hq, a module
# holding BRITE-TORONTO (NORAD 40020), a U/V "transponder" of one frequency
# each way (435.000 MHz down, 145.900 MHz up, as bench_doppler uses), and a
# full-duplex radio (Gpredict's radio type "Duplex TRX", split on VFO B)
# behind rigctld at 127.0.0.1:PORT.
#
#   gpredict_peer_home.sh HOME PORT [CYCLE_MS [REFRESH_MS]]
#
# CYCLE_MS is the radio controller's cycle (Gpredict's default 1000 ms when
# not given; this build's GUI allows 10 to 10000). REFRESH_MS is the
# module's data refresh, which is also how often the Doppler shift the
# radio controller sends is recomputed (default 300 ms; the preferences
# allow 100 to 10000). The satellite's .sat file comes from Gpredict's own
# satellites.dat on its first start (the same element set as tests/data).
#
# Gpredict is then run with its real-time clock shifted by a whole number
# of seconds, OFFSET, so that the 2018 pass comes in real time (libfaketime
# from Debian's faketime package; the monotonic clock left alone):
#   HOME=HOME FAKETIME="${OFFSET}s" FAKETIME_DONT_FAKE_MONOTONIC=1 \
#     LD_PRELOAD=/usr/lib/x86_64-linux-gnu/faketime/libfaketime.so.1 gpredict
# and OFFSET is doppler_from_log's --offset. In its window: the module's
# menu, Radio Control, T (tune to the transponder), Track, Engage. With a
# CYCLE_MS of 10 the spin button shows 10 but the controller keeps 1000 ms
# until the spin is moved: press + then -.
set -eu
home=$1
port=$2
cycle=${3:-}
refresh=${4:-}
conf="$home/.config/Gpredict"
mkdir -p "$conf/modules" "$conf/hwconf" "$conf/trsp" "$conf/satdata"

{
    echo "[GLOBAL]"
    echo "DEFAULT_QTH=JO65hq.qth"
    echo "OPEN_MODULES=Bench"
    echo "WINDOW_WIDTH=1500"
    echo "WINDOW_HEIGHT=950"
    echo "[TLE]"
    echo "AUTO_UPDATE_FREQ=0"
    if [ -n "$refresh" ]; then
        echo "[MODULES]"
        echo "DATA_TIMEOUT=$refresh"
    fi
} >"$conf/gpredict.cfg"

cat >"$conf/JO65hq.qth" <<EOF
[QTH]
LOCATION=JO65hq
DESCRIPTION=Slew's bench station (the centre of JO65hq)
LAT=55.6875
LON=12.625
ALT=0
TYPE=0
EOF

{
    echo "[GLOBAL]"
    echo "SATELLITES=40020;"
    echo "QTHFILE=JO65hq.qth"
    if [ -n "$refresh" ]; then
        echo "TIMEOUT=$refresh"
    fi
} >"$conf/modules/Bench.mod"

{
    echo "[Radio]"
    echo "Host=127.0.0.1"
    echo "Port=$port"
    echo "LO=0"
    echo "LO_UP=0"
    echo "Type=3"
    echo "PTT=0"
    echo "VFO_UP=2"
    echo "VFO_DOWN=1"
    echo "SIGNAL_AOS=false"
    echo "SIGNAL_LOS=false"
    if [ -n "$cycle" ]; then
        echo "Cycle=$cycle"
    fi
} >"$conf/hwconf/Bench.rig"

cat >"$conf/trsp/40020.trsp" <<EOF
[Bench U/V]
UP_LOW=145900000
UP_HIGH=145900000
DOWN_LOW=435000000
DOWN_HIGH=435000000
INVERT=false
MODE=USB
EOF
