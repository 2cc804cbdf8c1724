// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Carries one radio command out on a RadioLink for `slewctl --radio`: opens
// the link, sends the command, then reads the frequencies back and prints
// them, so what the radio holds is what the operator sees. Nothing waits:
// each step follows a signal, and a timeout gives up.

#include "consolerunner.h"
#include "radiocommand.h"

#include "radio/radiolink.h"

#include <QObject>
#include <QTimer>

namespace slew::console {

class RadioRunner : public QObject {
    Q_OBJECT
public:
    // `link` must outlive this; it is opened here.
    RadioRunner(radio::RadioLink *link, bool json, QObject *parent = nullptr);

    void run(const RadioCommand &command, int timeoutMs = 15000);

signals:
    void output(const QString &line);
    void problem(const QString &line);
    void finished(slew::console::ExitCode code);

private:
    void onState(radio::RadioLink::State state, const QString &detail);
    void send();
    void onRead(const radio::RadioFrequencies &frequencies);
    void finish(ExitCode code, const QString &why = {});

    radio::RadioLink *m_link;
    bool m_json;
    RadioCommand m_command;
    QTimer m_timeout;
    bool m_sent = false;
    bool m_done = false;
    bool m_failed = false;
};

} // namespace slew::console
