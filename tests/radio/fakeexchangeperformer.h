// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A backend for the exchange script's tests: it performs each command on a
// radio of its own (a receive and a transmit frequency, a step, split) and
// answers at once, or holds the answer until the test gives it, or answers
// what the test says. Commands read as short texts: `f`, `F 145800000`,
// `i`, `I 435000000`, `M USB 0`, `X LSB 0`, `S 1`, `s`, `n`.

#include "radio/exchangeperformer.h"

#include <QList>
#include <QStringList>

#include <functional>
#include <optional>
#include <utility>

class FakeExchangePerformer : public slew::radio::ExchangePerformer {
public:
    using Call = slew::radio::RadioCommand::Call;

    // The radio.
    QString receive = QStringLiteral("145800000"), transmit = QStringLiteral("435000000"),
            step = QStringLiteral("10"), split = QStringLiteral("0");
    bool splitKnown = true; // canReadSplit()
    // Answers wait for answerHeld() (or answer()) instead of coming at once.
    bool holding = false;
    bool holdOpening = false;
    // An answer of the test's own for a command; nothing: the radio's.
    std::function<std::optional<slew::radio::RadioAnswer>(const QString &text)> answerOverride;
    // What the script cannot send here, by the command's text.
    std::function<QString(const QString &text)> refuse;

    QStringList performed;
    QList<slew::radio::RadioCommand> commands;
    int opens = 0, closes = 0, aborts = 0;
    slew::radio::VfoLayout openedWith = slew::radio::VfoLayout::Split;

    QString reaching() const override { return QStringLiteral("reaching the fake radio"); }
    void open(slew::radio::VfoLayout layout) override
    {
        ++opens;
        openedWith = layout;
        m_held.reset();
        if (!holdOpening)
            emit opened();
    }
    void finishOpening() { emit opened(); }
    void loseRadio(const QString &reason) { emit lost(reason); }
    void perform(const slew::radio::RadioCommand &command) override
    {
        performed << text(command);
        commands << command;
        const slew::radio::RadioAnswer answer = answerTo(command);
        if (holding)
            m_held = answer;
        else
            emit answered(answer);
    }
    void close() override
    {
        ++closes;
        m_held.reset();
    }
    void abort() override
    {
        ++aborts;
        m_held.reset();
    }
    QString text(const slew::radio::RadioCommand &c) const override
    {
        const bool tx = c.path == slew::radio::RadioPath::Transmit;
        switch (c.call) {
        case Call::ReadFrequency:
            return tx ? QStringLiteral("i") : QStringLiteral("f");
        case Call::SetFrequency:
            return QStringLiteral("%1 %2").arg(QChar(tx ? u'I' : u'F')).arg(slew::radio::commandHzText(c.hz));
        case Call::SetMode:
            return QStringLiteral("%1 %2 %3").arg(QChar(tx ? u'X' : u'M')).arg(c.mode).arg(c.passbandHz);
        case Call::SetSplit:
            return c.on ? QStringLiteral("S 1") : QStringLiteral("S 0");
        case Call::ReadSplit:
            return QStringLiteral("s");
        case Call::ReadStep:
            return QStringLiteral("n");
        }
        return {};
    }
    QString refusal(const slew::radio::RadioCommand &command) const override
    {
        return refuse ? refuse(text(command)) : QString();
    }
    bool canReadSplit() const override { return splitKnown; }
    QString peerName() const override { return QStringLiteral("the fake"); }

    bool isHolding() const { return m_held.has_value(); }
    // The held answer goes back now.
    void answerHeld()
    {
        if (const std::optional<slew::radio::RadioAnswer> answer = std::exchange(m_held, std::nullopt))
            emit answered(*answer);
    }
    // An answer of the test's own, whatever is held (a late one included).
    void answer(const slew::radio::RadioAnswer &answer)
    {
        m_held.reset();
        emit answered(answer);
    }

private:
    slew::radio::RadioAnswer answerTo(const slew::radio::RadioCommand &c)
    {
        if (answerOverride) {
            if (std::optional<slew::radio::RadioAnswer> own = answerOverride(text(c)))
                return *own;
        }
        slew::radio::RadioAnswer a;
        const bool tx = c.path == slew::radio::RadioPath::Transmit;
        switch (c.call) {
        case Call::ReadFrequency:
            a.value = tx ? transmit : receive;
            break;
        case Call::SetFrequency:
            (tx ? transmit : receive) = slew::radio::commandHzText(c.hz);
            break;
        case Call::SetSplit:
            split = c.on ? QStringLiteral("1") : QStringLiteral("0");
            break;
        case Call::ReadSplit:
            a.value = split;
            break;
        case Call::ReadStep:
            a.value = step;
            break;
        case Call::SetMode:
            break;
        }
        return a;
    }

    std::optional<slew::radio::RadioAnswer> m_held;
};
