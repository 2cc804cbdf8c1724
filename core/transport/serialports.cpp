#include "serialports.h"

#include <QSerialPortInfo>

namespace slew::transport {

QString SerialPortDescription::uri() const
{
    return QStringLiteral("serial:") + location;
}

QList<SerialPortDescription> availableSerialPorts()
{
    QList<SerialPortDescription> ports;
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts()) {
        ports.append({info.portName(), info.systemLocation(), info.description(), info.manufacturer(),
                      info.serialNumber()});
    }
    return ports;
}

QList<qint32> commonBaudRates()
{
    return {19200, 9600, 38400, 57600, 115200};
}

} // namespace slew::transport
