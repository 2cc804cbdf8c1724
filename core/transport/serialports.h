#pragma once
// The serial ports this machine has, for the connection bar and the wizard.

#include <QList>
#include <QString>

namespace slew::transport {

struct SerialPortDescription {
    QString portName;     // "ttyUSB0"
    QString location;     // "/dev/ttyUSB0"
    QString description;  // "CP2102 USB to UART Bridge Controller"
    QString manufacturer;
    QString serialNumber;
    QString uri() const;  // "serial:/dev/ttyUSB0"
};

QList<SerialPortDescription> availableSerialPorts();

// The baud rates worth offering and probing, most common first.
QList<qint32> commonBaudRates();

} // namespace slew::transport
