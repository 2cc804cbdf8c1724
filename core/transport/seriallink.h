#pragma once
// A rotator controller on a serial port (USB adapter, RS-232, Bluetooth SPP).

#include "link.h"

#include <QSerialPort>

namespace slew::transport {

struct SerialSettings {
    QString portName; // "/dev/ttyUSB0", "COM3"
    qint32 baud = 19200; // Hamlib's default for its Easycomm backends
    QSerialPort::DataBits dataBits = QSerialPort::Data8;
    QSerialPort::Parity parity = QSerialPort::NoParity;
    QSerialPort::StopBits stopBits = QSerialPort::OneStop;
    QSerialPort::FlowControl flow = QSerialPort::NoFlowControl;
};

class SerialLink : public Link {
    Q_OBJECT
public:
    SerialLink(const QString &uri, const SerialSettings &settings, QObject *parent = nullptr);

    QIODevice *device() override { return &m_port; }
    void open() override;
    void close() override;
    bool isOpen() const override { return m_port.isOpen(); }

    const SerialSettings &settings() const { return m_settings; }

private:
    void onError(QSerialPort::SerialPortError error);

    SerialSettings m_settings;
    QSerialPort m_port;
};

} // namespace slew::transport
