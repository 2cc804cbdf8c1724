// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An in-process Link for session tests: no socket, no simulator. It keeps
// every byte the session writes, answers position queries from a position
// the test sets, and can report travel limits as a rotctld link does. It
// answers in Easycomm, or as a rotctld peer does when told so. The session
// cannot tell it from a serial port (transport/link.h).
//
//   registerScriptedLinkScheme();          // once, in initTestCase
//   session.connectTo("scripted:");        // the last one made is lastScriptedLink()

#include "model/rotatorlimits.h"
#include "protocol/encoder.h"
#include "protocol/message.h"
#include "protocol/parser.h"
#include "transport/link.h"
#include "transport/linkfactory.h"
#include "queuedreaddevice.h"

#include <QIODevice>
#include <QPointer>
#include <QTimer>

#include <optional>

// The byte stream behind the link: what the session writes is kept and
// answered; answers are read back as a device's would be.
class ScriptedDevice : public QueuedReadDevice {
public:
    double azimuth = 0.0;
    double elevation = 0.0;
    QByteArray written; // everything the session wrote, in order
    // What the session speaks to it: Easycomm (any flavour reads alike
    // here) or rotctld.
    slew::protocol::Dialect dialect = slew::protocol::Dialect::Easycomm3;
    // Position queries answered as K3NG's GS-232B emulation reports,
    // `AZ=059EL=025`, which no Easycomm reader reads: a wrong dialect.
    bool positionUnreadable = false;

    // Moves in what was written since `from`: set positions, speeds, bare
    // moves, park, home and register writes. Queries are not moves, and
    // neither is a zero speed: that is the hold that follows a stop.
    QStringList movesSince(qsizetype from) const
    {
        QStringList moves;
        slew::protocol::Parser parser(dialect);
        parser.feed(QByteArrayView(written).sliced(from), [&](const slew::protocol::Message &m) {
            using slew::protocol::Op;
            const bool speed = m.op == Op::VelocityLeft || m.op == Op::VelocityRight || m.op == Op::VelocityUp
                || m.op == Op::VelocityDown;
            const bool move = ((m.op == Op::Azimuth || m.op == Op::Elevation) && m.hasValue)
                || (speed && m.hasValue && m.value != 0.0) || m.op == Op::MoveLeft || m.op == Op::MoveRight || m.op == Op::MoveUp
                || m.op == Op::MoveDown || m.op == Op::Park || m.op == Op::Reset || m.op == Op::ConfigWrite;
            if (move)
                moves << QString::fromLatin1(slew::protocol::mnemonic(m.op)) + (m.hasValue ? QString::number(m.value) : QString());
        });
        return moves;
    }

protected:
    qint64 writeData(const char *data, qint64 size) override
    {
        written.append(data, size);
        m_line.append(data, size);
        for (qsizetype end; (end = m_line.indexOf('\n')) >= 0;) {
            answer(m_line.left(end));
            m_line.remove(0, end + 1);
        }
        return size;
    }

private:
    // Position queries get the position, and the capability probe's queries
    // a plain answer (so the probe ends at once, not after its timeouts);
    // commands go unanswered, as a controller leaves them.
    void answer(const QByteArray &line)
    {
        if (dialect == slew::protocol::Dialect::Rotctld) {
            answerAsRotctld(line.trimmed());
            return;
        }
        if (positionUnreadable && line.simplified() == "AZ EL") {
            deliver("AZ=059EL=025\r\n");
            return;
        }
        QByteArrayList out;
        for (const QByteArray &token : line.simplified().split(' ')) {
            if (token == "AZ")
                out << "AZ" + QByteArray::number(azimuth, 'f', 1);
            else if (token == "EL")
                out << "EL" + QByteArray::number(elevation, 'f', 1);
            else if (token == "VE")
                out << "VEScripted-1";
            else if (token == "GS" || token == "GE")
                out << token + "1";
            else if ((token.startsWith("IP") || token.startsWith("CR")) && token.size() > 2 && !token.contains(','))
                out << token + ",0";
        }
        if (out.isEmpty())
            return;
        deliver(out.join(' ') + '\n');
    }

    // rotctld answers every command: `p` with two bare lines, `_` with the
    // model's name, the rest with RPRT 0.
    void answerAsRotctld(const QByteArray &line)
    {
        using slew::protocol::encodeReport;
        using slew::protocol::Message;
        using slew::protocol::Op;
        if (line == "p")
            deliver(encodeReport(Message::number(Op::Azimuth, azimuth), dialect) + '\n'
                  + encodeReport(Message::number(Op::Elevation, elevation), dialect) + '\n');
        else if (line == "_")
            deliver("Scripted rotator\n");
        else if (!line.isEmpty())
            deliver("RPRT 0\n");
    }

    QByteArray m_line;
};

class ScriptedLink : public slew::transport::Link {
public:
    using Link::Link;

    // Limits to report once open, as rotctld's \dump_state does.
    std::optional<slew::model::RotatorLimits> reports;

    ScriptedDevice *scripted() { return &m_device; }
    QIODevice *device() override { return &m_device; }
    bool isOpen() const override { return m_device.isOpen(); }

    void open() override
    {
        m_device.open(QIODevice::ReadWrite);
        QTimer::singleShot(0, this, [this] {
            emit opened();
            if (reports)
                emit limitsReported(reports->azMin, reports->azMax, reports->elMin, reports->elMax);
        });
    }

    void close() override { m_device.close(); }

private:
    ScriptedDevice m_device;
};

// The link most recently made for a `scripted:` URI, and what it reports.
inline QPointer<ScriptedLink> &lastScriptedLink()
{
    static QPointer<ScriptedLink> last;
    return last;
}

inline std::optional<slew::model::RotatorLimits> &scriptedLinkReports()
{
    static std::optional<slew::model::RotatorLimits> reports;
    return reports;
}

// What the next scripted links answer in.
inline slew::protocol::Dialect &scriptedLinkDialect()
{
    static slew::protocol::Dialect dialect = slew::protocol::Dialect::Easycomm3;
    return dialect;
}

inline void registerScriptedLinkScheme()
{
    slew::transport::registerLinkScheme(QStringLiteral("scripted"), [](const QUrl &, const QString &uri) {
        auto link = std::make_unique<ScriptedLink>(uri);
        link->reports = scriptedLinkReports();
        link->scripted()->dialect = scriptedLinkDialect();
        lastScriptedLink() = link.get();
        return slew::transport::LinkResult{std::move(link), {}};
    });
}
