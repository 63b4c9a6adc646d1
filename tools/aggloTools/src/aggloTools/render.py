"""Off-screen pyvista pictures of particle fields.

Without a display (DISPLAY unset) VTK is told to render with OSMesa
straight away: it would otherwise try X first and print its "bad X server
connection" warning into the user's terminal before falling back to the
same OSMesa window."""

import os

import numpy as np


def _offscreen_window():
    if not os.environ.get("DISPLAY"):
        os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW",
                              "vtkOSOpenGLRenderWindow")


def particles_picture(path, positions, colour, bounds, title="",
                      colour_name="primaries per agglomerate",
                      single_size=2.0, cluster_size=9.0, camera=None,
                      window=(1600, 1000), axes=None, walls=(),
                      arrow=None):
    """Render particles at positions as points coloured by colour (the
    number of primaries): single primaries (colour 1) as small grey points,
    agglomerates as large points on a colour scale; the box outline is given
    by bounds (xmin, xmax, ymin, ymax, zmin, zmax). axes: the titles of
    the x, y, z axes (ticks and labels drawn); walls: (axis, position)
    planes drawn translucent (axis 0, 1, 2); arrow: (start, direction,
    label) drawn as an arrow with its label (a flow direction). Writes a
    PNG file."""
    _offscreen_window()
    import pyvista as pv
    pv.OFF_SCREEN = True

    x = np.asarray(positions, float)
    c = np.asarray(colour)
    pl = pv.Plotter(off_screen=True, window_size=list(window))
    pl.set_background("white")
    pl.add_mesh(pv.Box(bounds=bounds).outline(), color="black")
    single = c <= 1
    if single.any():
        pl.add_mesh(pv.PolyData(x[single]), color="grey",
                    point_size=single_size, render_points_as_spheres=True)
    legend = [["single primaries", "grey"]] if single.any() else []
    if (~single).any():
        pts = pv.PolyData(x[~single])
        top = int(c.max())
        if top == 2:
            # one size only: one colour and a legend entry, not a scale
            pl.add_mesh(pts, color="navy", point_size=cluster_size,
                        render_points_as_spheres=True)
            legend.append(["agglomerates of 2 primaries (the only size)",
                           "navy"])
        else:
            pts[colour_name] = c[~single].astype(float)
            # integer sizes: integer labels, at most 7 of them; the bar
            # upright at the right, clear of the axes' titles
            pl.add_mesh(pts, scalars=colour_name, cmap="plasma",
                        clim=[2, top], point_size=cluster_size,
                        render_points_as_spheres=True,
                        scalar_bar_args={
                            "title": colour_name, "color": "black",
                            "fmt": "%.0f", "n_labels": min(top - 1, 7),
                            "vertical": True, "position_x": 0.88,
                            "position_y": 0.25, "height": 0.5,
                            "width": 0.05})
    lo, hi = np.array(bounds[0::2], float), np.array(bounds[1::2], float)
    for axis, pos in walls:
        # the wall as the quad of the box's face at pos
        a, b = [k for k in range(3) if k != axis]
        corners = []
        for u, v in ((lo[a], lo[b]), (hi[a], lo[b]), (hi[a], hi[b]),
                     (lo[a], hi[b])):
            q = np.empty(3)
            q[axis], q[a], q[b] = pos, u, v
            corners.append(q)
        pl.add_mesh(pv.PolyData(np.array(corners), faces=[4, 0, 1, 2, 3]),
                    color="steelblue", opacity=0.3)
        # the wall named at its face's centre
        centre = 0.5 * (lo + hi)
        centre[axis] = pos
        pl.add_point_labels([centre], [f"wall, {'xyz'[axis]} = {pos:.3g} m"],
                            font_size=12, text_color="steelblue",
                            shape_opacity=0.0, show_points=False,
                            always_visible=True)
    if arrow:
        start, direction, label = arrow
        d = np.asarray(direction, float)
        pl.add_mesh(pv.Arrow(start=start, direction=d,
                             scale=float(np.linalg.norm(d))), color="red")
        # the label behind the arrow's tail, clear of its head, in front
        pl.add_point_labels([np.asarray(start) - 0.1 * d], [label],
                            font_size=14, text_color="red",
                            shape_opacity=0.0, show_points=False,
                            always_visible=True)
    if axes:
        # three labels per axis: the corners' ticks do not overlap
        pl.show_bounds(bounds=bounds, xtitle=axes[0], ytitle=axes[1],
                       ztitle=axes[2], color="black", font_size=10,
                       location="outer", fmt="%.3f", n_xlabels=3,
                       n_ylabels=3, n_zlabels=3)
    if legend:
        pl.add_text("\n".join(f"{c}: {t}" for t, c in legend),
                    position="upper_right", font_size=10, color="black")
    if title:
        pl.add_text(title, font_size=11, color="black")
    if camera:
        pl.camera_position = camera
    else:
        pl.view_isometric()
        # turned a little off the diagonal, so that the ticks of two axes
        # meeting at a corner of the box do not overlap; room for the
        # axes' ticks and titles where they are drawn
        pl.camera.Azimuth(12)
        pl.camera.Elevation(-8)
        pl.camera.zoom(0.95 if axes else 1.2)
    pl.screenshot(str(path))
    pl.close()
