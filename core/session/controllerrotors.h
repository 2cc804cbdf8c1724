#pragma once
// Every rotor of a multi-rotor controller beside the one a session drives.
//
// The operator window drives one rotor with its session (plot, jog, charts),
// but a Micro-2g has four on the same line, and the operator must see and
// command them all without reconnecting. ControllerRotors gives the window's
// session its link from a SharedLine (transport/sharedline.h) whenever the
// session's dialect has several rotors, and keeps a session of its own for
// each other rotor on that line: connected while the window's session is,
// with the same profile but its own calibration offsets (the ones saved for
// its URI, model/savedcalibration.h), and stopped with it.

#include "rotatorsession.h"

#include <QObject>

#include <memory>
#include <vector>

namespace slew::transport {
class SharedLine;
}

namespace slew::session {

class ControllerRotors : public QObject {
    Q_OBJECT
public:
    // Installs a link maker on `main`, which must outlive this object.
    explicit ControllerRotors(RotatorSession *main, QObject *parent = nullptr);
    ~ControllerRotors() override;

    // The rotors on the line, 1..n in order, the main session's among them;
    // empty unless the main session is connected to a multi-rotor controller.
    QList<RotatorSession *> rotors() const;
    int rotorCount() const { return int(rotors().size()); }
    RotatorSession *main() const { return m_main; }
    // The session of rotor n (1..4), or null.
    RotatorSession *rotor(int n) const;
    transport::SharedLine *line() const { return m_line.get(); }

public slots:
    // Stops every other rotor on the line (the window's Stop stops its own
    // session itself); returns how many stops went out.
    int stopOthers(const QString &cause);

signals:
    // The list of rotors changed (a multi-rotor controller came or went).
    void rotorsChanged();

private:
    transport::LinkResult makeLink(const QString &uri);
    void onMainState(RotatorSession::State state);
    void clearOthers();
    model::RotatorProfile profileOf(int rotor) const;

    RotatorSession *m_main;
    std::unique_ptr<transport::SharedLine> m_line;
    // Rotor n's session at [n - 1]; the main session's slot stays empty.
    std::vector<std::unique_ptr<RotatorSession>> m_others;
};

} // namespace slew::session
