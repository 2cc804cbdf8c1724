#pragma once
// A small compass for one azimuth-only rotor: north up, the antenna's
// heading as a needle, where it is going as a hollow marker. The polar plot
// is the full instrument for the window's own rotor; this is the glance at
// the others beside it.

#include <QWidget>

#include <optional>

namespace slew::ui {

class CompassDial : public QWidget {
    Q_OBJECT
public:
    explicit CompassDial(QWidget *parent = nullptr);

    // Degrees clockwise from north; stale draws the needle grey.
    void setHeading(double degrees, bool stale);
    void setTarget(std::optional<double> degrees);
    void clear();

    std::optional<double> heading() const { return m_heading; }
    std::optional<double> target() const { return m_target; }

    QSize sizeHint() const override { return {72, 72}; }
    QSize minimumSizeHint() const override { return {56, 56}; }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    std::optional<double> m_heading;
    std::optional<double> m_target;
    bool m_stale = true;
};

} // namespace slew::ui
