#pragma once
// Moves a manual-clock simulator on by a fixed slice every time the event
// loop comes round, so a test runs simulated seconds in wall milliseconds
// while every reply still travels through the event loop as it would on a
// real line. Samples are stamped with the simulator's clock (SampleClock),
// so the figures are the same however fast the machine is.

#include "sim/simulator.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

class SimulatorPump : public QObject {
public:
    explicit SimulatorPump(double sliceSeconds = 0.005, QObject *parent = nullptr)
        : QObject(parent), m_slice(sliceSeconds)
    {
        m_timer.setInterval(0);
        QObject::connect(&m_timer, &QTimer::timeout, this, [this] {
            if (m_sim)
                m_sim->advance(m_slice);
        });
    }
    void drive(slew::sim::Simulator *sim)
    {
        m_sim = sim;
        m_timer.start();
    }
    void pause() { m_timer.stop(); }
    void resume() { m_timer.start(); }

private:
    QPointer<slew::sim::Simulator> m_sim;
    double m_slice;
    QTimer m_timer;
};
