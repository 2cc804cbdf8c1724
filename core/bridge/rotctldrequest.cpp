// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotctldrequest.h"

#include <QList>
#include <QObject>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace slew::bridge {

namespace {

using Kind = RotctldRequest::Kind;

struct CommandName {
    char shortName;
    const char *longName;
    Kind kind;
    int argumentCount;
};

constexpr CommandName kCommands[] = {
    {'P', "set_pos", Kind::SetPosition, 2}, {'p', "get_pos", Kind::GetPosition, 0},
    {'S', "stop", Kind::Stop, 0},           {'K', "park", Kind::Park, 0},
    {'R', "reset", Kind::Reset, 1},         {'M', "move", Kind::Move, 2},
    {'_', "get_info", Kind::GetInfo, 0},    {'q', "quit", Kind::Quit, 0},
    {'Q', "quit", Kind::Quit, 0},
};

const CommandName *findShort(char c)
{
    for (const CommandName &c2 : kCommands) {
        if (c2.shortName == c)
            return &c2;
    }
    return nullptr;
}

const CommandName *findLong(QByteArrayView name)
{
    for (const CommandName &c : kCommands) {
        if (name == c.longName)
            return &c;
    }
    return nullptr;
}

bool readNumber(const QByteArray &text, double *out)
{
    QByteArray t = text;
    t.replace(',', '.'); // Hamlib reads numbers in the C locale and accepts ',' too
    bool ok = false;
    const double v = t.toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return false;
    *out = v;
    return true;
}

bool readInt(const QByteArray &text, int *out)
{
    bool ok = false;
    const int v = text.toInt(&ok);
    if (!ok)
        return false;
    *out = v;
    return true;
}

// `%.Nf` in the C locale, as rotctld prints. snprintf returns the length the
// whole number needs, which for a large double (`P 1e308 0` is a valid
// set_pos, and a rotctld:// peer may report anything) is far more than a
// small buffer: the buffer holds any finite double, and the length is
// clamped to what was written.
QByteArray fixed(double v, int decimals)
{
    char buffer[400]; // DBL_MAX is 309 digits before the point
    const int n = std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return QByteArray(buffer, std::clamp(n, 0, int(sizeof buffer) - 1));
}

QByteArray fixed2(double v)
{
    return fixed(v, 2);
}

QByteArray fixed6(double v)
{
    return fixed(v, 6);
}

QByteArray rprt(int code)
{
    return "RPRT " + QByteArray::number(code == 0 ? 0 : -std::abs(code));
}

// The extended header: "set_pos: 10 20" (arguments echoed) or "get_pos:".
QByteArray header(const RotctldRequest &r)
{
    QByteArray h = r.name + ':';
    if (!r.arguments.isEmpty())
        h += ' ' + r.arguments;
    return h;
}

} // namespace

QString describeHamlibError(int code)
{
    if (const char *text = protocol::hamlibErrorText(code))
        return QObject::tr(text);
    return QObject::tr("error %1").arg(code);
}

RotctldRequest parseRotctldLine(QByteArrayView line)
{
    RotctldRequest r;
    QByteArray text = line.toByteArray().trimmed();
    if (text.isEmpty()) {
        r.kind = Kind::Malformed;
        r.error = QObject::tr("empty command");
        return r;
    }
    // The extended prefix: '+' or another punctuation character (not '\\',
    // which starts a long name, and not '_', which is get_info).
    const char first = text[0];
    if (first == '+' || first == ';' || first == '|' || first == ',') {
        r.extended = true;
        r.separator = first == '+' ? '\n' : first;
        text = text.mid(1).trimmed();
        if (text.isEmpty()) {
            r.kind = Kind::Malformed;
            r.error = QObject::tr("no command after '%1'").arg(QLatin1Char(first));
            return r;
        }
    }

    const CommandName *command = nullptr;
    QByteArray rest;
    if (text.startsWith('\\')) {
        const qsizetype space = text.indexOf(' ');
        const QByteArray name = text.mid(1, space < 0 ? -1 : space - 1);
        if (name == "dump_state") {
            r.kind = Kind::DumpState;
            r.name = name;
            return r;
        }
        command = findLong(name);
        rest = space < 0 ? QByteArray() : text.mid(space + 1);
        if (!command) {
            r.error = QObject::tr("unknown command '\\%1'").arg(QString::fromLatin1(name.left(40)));
            return r;
        }
    } else {
        command = findShort(text[0]);
        rest = text.mid(1);
        if (!command) {
            r.error = QObject::tr("unknown command '%1'").arg(QString::fromLatin1(text.left(1)));
            return r;
        }
    }
    r.kind = command->kind;
    r.name = command->longName;
    const QList<QByteArray> args = rest.simplified().split(' ');
    const int given = rest.simplified().isEmpty() ? 0 : int(args.size());
    if (given != command->argumentCount) {
        r.kind = Kind::Malformed;
        r.error = QObject::tr("%1 takes %2 argument(s), got %3")
                      .arg(QString::fromLatin1(r.name))
                      .arg(command->argumentCount)
                      .arg(given);
        return r;
    }
    r.arguments = rest.simplified();
    bool ok = true;
    switch (r.kind) {
    case Kind::SetPosition:
        ok = readNumber(args[0], &r.az) && readNumber(args[1], &r.el);
        break;
    case Kind::Move:
        ok = readInt(args[0], &r.direction) && readInt(args[1], &r.speed);
        break;
    case Kind::Reset:
        ok = readInt(args[0], &r.resetType);
        break;
    default:
        break;
    }
    if (!ok) {
        r.kind = Kind::Malformed;
        r.error = QObject::tr("%1: '%2' is not a number")
                      .arg(QString::fromLatin1(r.name), QString::fromLatin1(r.arguments.left(60)));
    }
    return r;
}

QByteArray formatStatus(const RotctldRequest &r, int code)
{
    if (!r.extended || r.name.isEmpty())
        return rprt(code) + '\n';
    return header(r) + r.separator + rprt(code) + '\n';
}

QByteArray formatPosition(const RotctldRequest &r, double az, double el)
{
    if (!r.extended)
        return fixed2(az) + '\n' + fixed2(el) + '\n';
    const char s = r.separator;
    return header(r) + s + "Azimuth: " + fixed2(az) + s + "Elevation: " + fixed2(el) + s + rprt(0) + '\n';
}

QByteArray formatInfo(const RotctldRequest &r, const QString &info)
{
    const QByteArray text = info.toLatin1();
    if (!r.extended)
        return text + '\n';
    const char s = r.separator;
    return header(r) + s + "Info: " + text + s + rprt(0) + '\n';
}

QByteArray formatDumpState(const DumpStateLimits &l)
{
    return "1\n" + QByteArray::number(l.model) + "\nmin_az=" + fixed6(l.minAz) + "\nmax_az=" + fixed6(l.maxAz)
        + "\nmin_el=" + fixed6(l.minEl) + "\nmax_el=" + fixed6(l.maxEl) + "\nsouth_zero=0\nrot_type=AzEl\ndone\n";
}

} // namespace slew::bridge
