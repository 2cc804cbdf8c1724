// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The side of the in-process Hamlib radio link (hamlibradio.h) that calls
// libhamlib. Hamlib's calls block: a serial read waits out its timeout and
// its retries (about 10 s for an IC-9700 that never answers its open).
// So the RIG lives on a thread of its own, owned by the HamlibWorker there,
// and every rig_* call runs on that thread; the link on the main thread
// posts one job at a time and takes the result from a queued signal.
//
// Nothing on the main thread ever waits for the worker, not even to end
// it. finishLater() posts the last job: it closes and frees the RIG on the
// worker's thread, whenever the call before it returns, and ends the
// thread; the thread and the worker then delete themselves. A worker may
// so outlive its link by as long as Hamlib takes to give up.
//
// Jobs of a session the link has left (it closed, reopened or went away)
// are skipped unheard: the link raises the shared session number, and the
// worker compares before it calls Hamlib. Closing and finishing always
// run.
//
// Hamlib keeps state for the whole process without a lock (the list of
// open rigs, the buffers behind its error text), so the workers of all
// links take turns: one Hamlib call at a time in the process. A radio
// stuck in a timeout delays another link's calls, never the main thread.

#include "hamliburi.h"

#include <QMetaType>
#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

struct s_rig; // Hamlib's RIG

namespace slew::radio {

enum class HamlibCall {
    Open,         // rig_init, the settings, rig_open
    GetFreq,      // rig_get_freq
    SetFreq,      // rig_set_freq
    SetSplitFreq, // rig_set_split_freq (RIG_VFO_TX)
    GetSplitFreq, // rig_get_split_freq (RIG_VFO_TX)
    GetSplit,     // rig_get_split_vfo: whether split is on
    SplitOn,      // rig_set_split_vfo(current, on, VFO B)
    SplitOff,     // rig_set_split_vfo(current, off, VFO A)
    SetMode,      // rig_set_mode
    SetSplitMode, // rig_set_split_mode (RIG_VFO_TX)
    GetStep,      // rig_get_ts, else the model's finest step for the mode
    Close,        // rig_close and rig_cleanup
    Finish,       // Close, then the thread ends
};

// The VFO a call names. The split calls name the transmit VFO (RIG_VFO_TX).
enum class HamlibVfo { Current, Main, Sub };

struct HamlibJob {
    int session = 0;
    HamlibCall call = HamlibCall::GetFreq;
    HamlibVfo vfo = HamlibVfo::Current;
    double hz = 0;         // SetFreq, SetSplitFreq
    quint64 mode = 0;      // SetMode, SetSplitMode: Hamlib's rmode_t
    qint64 passbandHz = 0; // SetMode, SetSplitMode: 0 the mode's default, -1 unchanged
    quint64 serial = 0;    // the link's number for this job, given back with its result
};

struct HamlibResult {
    int session = 0;
    quint64 serial = 0; // the job's
    HamlibCall call = HamlibCall::GetFreq;
    int code = 0;     // what Hamlib returned: 0, or a negative RIG_E... code
    double value = 0; // a frequency or a step read, in Hz; GetSplit: 1 when on
    QString detail;   // Open: what was wrong beyond Hamlib's words
};

class HamlibWorker : public QObject {
    Q_OBJECT
public:
    // A worker on a new thread, started. `session` is shared with the link.
    static HamlibWorker *start(const HamlibRadioConfig &config, std::shared_ptr<const std::atomic<int>> session);

    // Queues a job; any thread. Never after finishLater().
    void post(const HamlibJob &job);
    // Queues the last job: the RIG closed and freed, the thread ended, and
    // the thread and this deleted.
    void finishLater();

    // Workers whose thread has not yet been deleted, across the process.
    static int liveCount();

    ~HamlibWorker() override;

signals:
    void done(const slew::radio::HamlibResult &result);

private:
    HamlibWorker(const HamlibRadioConfig &config, std::shared_ptr<const std::atomic<int>> session);
    void run(const HamlibJob &job);
    int openRig(QString *detail);
    int setting(const char *name, const QByteArray &value, QString *detail);
    double tuningStepHz(HamlibVfo vfo);
    void releaseRig();

    const HamlibRadioConfig m_config;
    const std::shared_ptr<const std::atomic<int>> m_session;
    s_rig *m_rig = nullptr;
};

} // namespace slew::radio

Q_DECLARE_METATYPE(slew::radio::HamlibResult)
