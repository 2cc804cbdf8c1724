// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Single exchanges with libhamlib in this process, for the in-process radio
// link (hamlibradio.h, which says which Hamlib call each command is).
//
// Each command is one job posted to the link's worker thread
// (hamlibworker.h), and its result comes back as a queued signal: nothing
// here waits for Hamlib, neither to open, nor to close, nor when this is
// destroyed. Opening is rig_open (a serial model's device, rate and CI-V
// address set first): its failure loses the radio with Hamlib's words and
// what the device file says. A result of a session left (closed, reopened,
// aborted) or of a job not on the wire now is dropped unheard.

#include "exchangeperformer.h"
#include "hamliburi.h"
#include "hamlibworker.h"

#include <atomic>
#include <memory>

namespace slew::radio {

class HamlibPerformer : public ExchangePerformer {
    Q_OBJECT
public:
    explicit HamlibPerformer(HamlibRadioConfig config, QObject *parent = nullptr);
    ~HamlibPerformer() override;

    QString reaching() const override;
    void open(VfoLayout layout) override;
    void perform(const RadioCommand &command) override;
    void close() override { leaveSession(); }
    void abort() override { leaveSession(); }
    QString text(const RadioCommand &command) const override;
    // A mode name rig_parse_mode does not know.
    QString refusal(const RadioCommand &command) const override;
    QString peerName() const override { return QStringLiteral("Hamlib"); }

    const HamlibRadioConfig &config() const { return m_config; }

private:
    HamlibJob jobFor(const RadioCommand &command) const;
    void post(HamlibJob job);
    void onDone(const HamlibResult &result);
    // The session ends: the worker skips what is left of it and frees the radio.
    void leaveSession();

    const HamlibRadioConfig m_config;
    HamlibWorker *m_worker = nullptr; // made at the first open(); ends itself after this is gone
    std::shared_ptr<std::atomic<int>> m_session;
    quint64 m_lastSerial = 0; // the number of the job on the wire (HamlibJob::serial)
    VfoLayout m_layout = VfoLayout::Split;
};

} // namespace slew::radio
