// SPDX-License-Identifier: GPL-3.0-or-later
#include "micro2glistings.h"

#include <QByteArray>
#include <QList>

namespace slew::protocol {

namespace {

constexpr int kAdcMax = 4095; // a 12-bit converter

// A whole number of 1..digits digits, and nothing else.
std::optional<int> whole(QByteArrayView text, int digits)
{
    if (text.isEmpty() || text.size() > digits)
        return std::nullopt;
    int value = 0;
    for (char c : text) {
        if (c < '0' || c > '9')
            return std::nullopt;
        value = value * 10 + (c - '0');
    }
    return value;
}

QList<QByteArrayView> words(QByteArrayView line, bool commasToo)
{
    QList<QByteArrayView> out;
    auto isGap = [&](char c) { return c == ' ' || c == '\t' || (commasToo && c == ','); };
    for (qsizetype i = 0; i < line.size();) {
        while (i < line.size() && isGap(line[i]))
            ++i;
        const qsizetype start = i;
        while (i < line.size() && !isGap(line[i]))
            ++i;
        if (i > start)
            out.append(line.sliced(start, i - start));
    }
    return out;
}

bool isZGroup(QByteArrayView head, char rotor, char which)
{
    return head.size() == 3 && (head[0] == 'Z' || head[0] == 'z') && head[1] == rotor
        && (head[2] == which || head[2] == char(which - 'A' + 'a'));
}

// `3990=000`: a reading and a bearing.
bool stop(QByteArrayView text, int *adc, int *bearing)
{
    const qsizetype equals = text.indexOf('=');
    if (equals < 0)
        return false;
    const auto counts = whole(text.first(equals), 4);
    const auto degrees = whole(text.sliced(equals + 1), 3);
    if (!counts || !degrees || *counts > kAdcMax || *degrees > 359)
        return false;
    *adc = *counts;
    *bearing = *degrees;
    return true;
}

} // namespace

std::optional<Micro2gCalibration> readMicro2gCalibration(QByteArrayView line)
{
    const QList<QByteArrayView> w = words(line, false);
    if (w.size() != 6 || w[0].size() != 3)
        return std::nullopt;
    const char rotor = w[0][1];
    if (rotor < '1' || rotor > '4')
        return std::nullopt;
    if (!isZGroup(w[0], rotor, 'L') || !isZGroup(w[2], rotor, 'R') || !isZGroup(w[4], rotor, 'D'))
        return std::nullopt;
    Micro2gCalibration c;
    c.rotor = rotor - '0';
    const auto range = whole(w[5], 3);
    if (!stop(w[1], &c.leftAdc, &c.leftBearing) || !stop(w[3], &c.rightAdc, &c.rightBearing) || !range)
        return std::nullopt;
    c.degreeRange = *range;
    return c;
}

QList<Micro2gAdcReading> readMicro2gAdcReadings(QByteArrayView listing)
{
    QList<Micro2gAdcReading> out;
    for (QByteArrayView item : words(listing, true)) {
        const bool named = item.size() > 3 && (item[0] == 'V' || item[0] == 'v') && item[1] >= '1' && item[1] <= '4'
            && item[2] == '=';
        const auto counts = named ? whole(item.sliced(3), 4) : std::nullopt;
        if (!counts || *counts > kAdcMax)
            return {};
        out.append(Micro2gAdcReading{item[1] - '0', *counts});
    }
    return out;
}

} // namespace slew::protocol
