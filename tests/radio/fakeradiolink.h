// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A radio for the Doppler tests, on the test's own clock: a frequency sent
// is taken `latencyMs` later (as a CAT bus and a radio's firmware take
// time), a read answers what the radio holds at that moment, and the
// operator can turn its dial. The real links (rigctld, libhamlib) have
// their own tests against Hamlib's programs.

#include "radio/radiolink.h"

#include <QStringList>

#include <deque>
#include <optional>

class FakeRadioLink : public slew::radio::RadioLink {
public:
    int latency = 0;
    double step = 1.0;
    QStringList sent;

    void open() override { m_state = State::Open; }
    void close() override { m_state = State::Closed; }
    State state() const override { return m_state; }
    QString uri() const override { return QStringLiteral("fake:"); }
    void setReceiveHz(double hz) override { schedule(true, hz); }
    void setTransmitHz(double hz) override { schedule(false, hz); }
    void setSplit(bool) override {}
    void setMode(const QString &, int) override {}
    void setTransmitMode(const QString &, int) override {}
    void readFrequencies() override
    {
        if (failReads)
            return; // a read the radio did not answer: a real link says so in commandFailed, and reads nothing
        slew::radio::RadioFrequencies f;
        f.receiveHz = receive;
        f.transmitHz = transmit;
        if (answerLater)
            m_unanswered.push_back(f); // what the radio held when asked
        else
            emit frequenciesRead(f);
    }
    // Reads are answered by answerReads(), as a real link's answer comes
    // back after commands sent meanwhile have been queued.
    bool answerLater = false;
    bool failReads = false;
    void answerReads()
    {
        std::deque<slew::radio::RadioFrequencies> due;
        due.swap(m_unanswered);
        for (const auto &f : due)
            emit frequenciesRead(f);
    }
    double tuningStepHz() const override { return step; }
    int latencyMs() const override { return latency; }
    void setMinimumIntervalMs(int) override {}
    void dropWaiting() override {} // a command here is on the radio's bus at once

    // The radio's clock: what was sent takes effect once its latency is over.
    void advanceTo(qint64 ms)
    {
        now = ms;
        while (!m_pending.empty() && m_pending.front().atMs <= now) {
            (m_pending.front().receive ? receive : transmit) = m_pending.front().hz;
            m_pending.pop_front();
        }
    }
    // The operator's hand on the receive dial.
    void turnDialTo(double hz) { receive = hz; }

    std::optional<double> receive, transmit; // what the radio holds
    qint64 now = 0;

private:
    void schedule(bool isReceive, double hz)
    {
        sent << QStringLiteral("%1 %2").arg(isReceive ? u'F' : u'I').arg(hz, 0, 'f', 0);
        m_pending.push_back({isReceive, hz, now + latency});
        advanceTo(now);
    }
    struct Pending {
        bool receive;
        double hz;
        qint64 atMs;
    };
    std::deque<Pending> m_pending;
    std::deque<slew::radio::RadioFrequencies> m_unanswered;
    State m_state = State::Open;
};
