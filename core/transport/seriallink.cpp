#include "seriallink.h"

#include <QTimer>

namespace slew::transport {

SerialLink::SerialLink(const QString &uri, const SerialSettings &settings, QObject *parent)
    : Link(uri, parent), m_settings(settings)
{
    connect(&m_port, &QSerialPort::errorOccurred, this, &SerialLink::onError);
}

void SerialLink::open()
{
    if (m_port.isOpen())
        return;
    m_port.setPortName(m_settings.portName);
    m_port.setBaudRate(m_settings.baud);
    m_port.setDataBits(m_settings.dataBits);
    m_port.setParity(m_settings.parity);
    m_port.setStopBits(m_settings.stopBits);
    m_port.setFlowControl(m_settings.flow);
    // QSerialPort::open() does not wait on the device, only on the OS; the
    // result is still reported from the event loop so that every link kind
    // signals the same way, after open() has returned.
    if (m_port.open(QIODevice::ReadWrite)) {
        QTimer::singleShot(0, this, [this] {
            if (m_port.isOpen())
                emit opened();
        });
    } else {
        const QString reason = tr("%1: cannot open %2: %3").arg(uri(), m_settings.portName, m_port.errorString());
        QTimer::singleShot(0, this, [this, reason] { emit failed(reason); });
    }
}

void SerialLink::close()
{
    m_port.close();
}

void SerialLink::onError(QSerialPort::SerialPortError error)
{
    // Unplugging a USB adapter shows up as a resource or permission error on
    // an open port; errors before or during open are reported by open().
    if (!m_port.isOpen())
        return;
    if (error == QSerialPort::ResourceError || error == QSerialPort::PermissionError
        || error == QSerialPort::DeviceNotFoundError) {
        const QString reason = tr("%1: serial port lost: %2").arg(uri(), m_port.errorString());
        m_port.close();
        emit lost(reason);
    }
}

} // namespace slew::transport
