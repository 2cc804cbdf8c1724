// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where an MQTT broker is and who Slew is there, from a URL the operator
// writes: `mqtts://USER@HOST:8883` (the station service's --mqtt),
// `mqtts://USER@HOST:8883/NAME` (a window opening one station; without NAME,
// the station network), with `?cafile=PATH` naming the certificate
// authority the broker's certificate must be signed by. Pure code.
//
// What is refused, each with why: a password in the URL (it would show in
// `ps` and the shell's history; it comes from a file or the environment,
// brokerpassword.h), plain `mqtt://` to any host but this machine's own
// loopback (the password and every command would cross the network in the
// clear), a station name MQTT would read as a wildcard or a level, and any
// query but `cafile`.

#include <QString>

#include <optional>

namespace slew::remote {

inline constexpr quint16 kMqttPort = 1883;
inline constexpr quint16 kMqttsPort = 8883;
// A station's name is one topic level: letters, digits, '-', '_', '.'.
inline constexpr int kLongestStationName = 64;

struct BrokerAddress {
    bool tls = true;
    QString user;        // empty: none sent
    QString host;
    quint16 port = kMqttsPort;
    QString stationName; // the URL's path, when it names one
    QString caFile;      // ?cafile=; empty: the system's certificate authorities

    // "mqtts://ops@broker.example:8883", without the name or the query:
    // what the log and the window say they are connected to.
    QString display() const;
};

// The address a URL names, or nothing with *error saying what is wrong in
// words an operator can act on.
std::optional<BrokerAddress> parseBrokerAddress(const QString &url, QString *error);

// True for a name that only this machine answers: 127.0.0.0/8, ::1, or
// "localhost" (which Debian resolves to those and nothing else).
bool isLoopbackHost(const QString &host);

// Empty when `name` can be a station's topic level, else why not.
QString checkStationName(const QString &name);

} // namespace slew::remote
