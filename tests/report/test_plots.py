"""Each plotting function draws the results on the ax it is given and returns that ax."""

from __future__ import annotations

import numpy as np
import pytest
from matplotlib.figure import Figure
from matplotlib.patches import Polygon, Rectangle

from machdyn.linkage import harmonics
from machdyn.report import plots


def _ax(polar: bool = False):
    fig = Figure()
    return fig.add_subplot(projection="polar") if polar else fig.add_subplot()


def _line_with(ax, ydata) -> bool:
    return any(
        len(line.get_ydata()) == len(ydata) and np.allclose(line.get_ydata(), ydata) for line in ax.get_lines()
    )


def test_plot_mechanism(any_analysis):
    a = any_analysis
    ax = _ax()
    assert plots.plot_mechanism(ax, a.mechanism, a.kinematics, positions=3) is ax
    # the crank pin A at the first position is drawn where the kinematics puts it
    pin = a.kinematics.point("crank.A")
    xy = np.concatenate([np.column_stack([ln.get_xdata(), ln.get_ydata()]) for ln in ax.get_lines()])
    assert np.any(np.all(np.isclose(xy, [pin.x[0], pin.y[0]]), axis=1))
    assert any(isinstance(p, Polygon) for p in ax.patches)  # ground pivot symbols
    assert ax.get_xlabel() == "x [m]" and ax.get_ylabel() == "y [m]"
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "crank" in labels


def test_plot_mechanism_draws_slider_and_requested_positions(slider_crank_analysis):
    a = slider_crank_analysis
    ax = plots.plot_mechanism(_ax(), a.mechanism, a.kinematics, positions=[0.0, np.pi])
    assert sum(isinstance(p, Rectangle) and p.get_width() > 0 for p in ax.patches) >= 2
    assert "0°" in ax.get_title(loc="left") and "180°" in ax.get_title(loc="left")


@pytest.mark.parametrize("quantity", ["displacement", "velocity", "acceleration"])
def test_plot_point_motion_of_a_point(four_bar_analysis, quantity):
    kin = four_bar_analysis.kinematics
    ax = _ax()
    assert plots.plot_point_motion(ax, kin, "coupler.P", quantity) is ax
    p = kin.point("coupler.P")
    expected = {"displacement": p.x, "velocity": p.speed, "acceleration": p.ay}[quantity]
    assert _line_with(ax, expected)
    np.testing.assert_allclose(ax.get_lines()[0].get_xdata(), np.degrees(kin.crank_angle))
    assert "[m" in ax.get_ylabel() and "deg" in ax.get_xlabel()


def test_plot_point_motion_of_slider_and_rocker(slider_crank_analysis, four_bar_analysis):
    ax = plots.plot_point_motion(_ax(), slider_crank_analysis.kinematics, "slider", "acceleration")
    assert _line_with(ax, slider_crank_analysis.kinematics.slide("slider").a)
    assert ax.get_ylabel() == "Acceleration [m/s²]"
    ax = plots.plot_point_motion(_ax(), four_bar_analysis.kinematics, "rocker", "velocity")
    assert _line_with(ax, four_bar_analysis.kinematics.body("rocker").omega)
    assert ax.get_ylabel() == "Velocity [rad/s]"
    with pytest.raises(ValueError, match="quantity"):
        plots.plot_point_motion(_ax(), four_bar_analysis.kinematics, "rocker", "jerk")


def test_plot_joint_polar(four_bar_analysis):
    forces = four_bar_analysis.forces
    ax = _ax(polar=True)
    assert plots.plot_joint_polar(ax, forces, "B") is ax
    r = forces.joint("B")
    line = ax.get_lines()[0]
    np.testing.assert_allclose(line.get_ydata(), r.magnitude)
    np.testing.assert_allclose(np.cos(line.get_xdata()) * line.get_ydata(), r.fx, atol=1e-9)
    assert "B" in ax.get_title(loc="left")
    # on Cartesian axes: the hodograph Fy over Fx
    cart = plots.plot_joint_polar(_ax(), forces, "B")
    np.testing.assert_allclose(cart.get_lines()[0].get_xdata(), r.fx)
    assert cart.get_xlabel() == "Fx [N]"


def test_plot_shaking_force_polar_and_moment(slider_crank_analysis):
    forces = slider_crank_analysis.forces
    ax = _ax(polar=True)
    assert plots.plot_shaking_force_polar(ax, forces) is ax
    fx, fy = forces.frame_force
    np.testing.assert_allclose(ax.get_lines()[0].get_ydata(), np.hypot(fx, fy))
    ax2 = _ax()
    assert plots.plot_shaking_moment(ax2, forces, about=(0.1, 0.0)) is ax2
    assert _line_with(ax2, forces.shaking_moment(about=(0.1, 0.0)))
    assert "N·m" in ax2.get_ylabel()


def test_plot_torque_power(four_bar_analysis):
    forces = four_bar_analysis.forces
    ax = _ax()
    assert plots.plot_torque_power(ax, forces) is ax
    assert _line_with(ax, forces.driving_torque)
    assert ax.get_ylabel() == "Driving torque [N·m]"
    # constant speed: the power is a second scale of the torque axis
    assert "Input power [W]" in ax.power_axis.get_ylabel()


def test_plot_torque_power_with_varying_speed(four_bar_analysis):
    from machdyn.linkage import analyse, crank_angles

    phi = crank_angles(90)
    a = analyse(four_bar_analysis.mechanism, phi, 20.0 + np.sin(phi), diagnostics=False)
    ax = plots.plot_torque_power(_ax(), a.forces)
    assert _line_with(ax.power_axis, a.forces.input_power)


def test_plot_energy(any_analysis):
    e = any_analysis.energy
    ax = _ax()
    assert plots.plot_energy(ax, e) is ax
    assert _line_with(ax, e.kinetic_total)
    assert _line_with(ax, e.total)
    assert ax.get_ylabel() == "Energy [J]"
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "kinetic total" in labels and "total" in labels
    ax2 = _ax()
    assert plots.plot_reduced_inertia(ax2, e, any_analysis.kinematics.crank_angle) is ax2
    assert _line_with(ax2, e.reduced_inertia)


def test_plot_harmonics(four_bar_analysis):
    a = four_bar_analysis
    h = harmonics(a.forces.driving_torque, a.kinematics.crank_angle, orders=6)
    ax = _ax()
    assert plots.plot_harmonics(ax, h, unit="N·m") is ax
    heights = [p.get_height() for p in ax.patches]
    np.testing.assert_allclose(heights[:6], h.amplitude)
    assert heights[6] == pytest.approx(abs(float(h.mean)))
    assert ax.get_ylabel() == "Amplitude [N·m]"


def test_design_variants_draw_one_line_each(sweep_analysis):
    forces = sweep_analysis.forces
    ax = plots.plot_shaking_moment(_ax(), forces)
    assert len(ax.get_lines()) == 1 + 3  # the zero line and one curve per design
    ax = plots.plot_shaking_moment(_ax(), forces, design=1)
    assert _line_with(ax, forces.shaking_moment()[1])
    ax = plots.plot_mechanism(_ax(), sweep_analysis.mechanism, sweep_analysis.kinematics, design=2)
    assert ax.get_lines()
