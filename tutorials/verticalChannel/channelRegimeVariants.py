"""verticalChannel regime study: its variants, in order (a preset each),
with what each changes from `small`; channelRegime runs and posts them,
channelRegimePairs derives from their presets which pairs are one
shortcut apart."""


#: The variants, in order: name (= preset), what it changes from `small`
VARIANTS = (
    ("small", "the main job's preset: 32^3, 1e5, phases 60/10/30/60 T*"),
    ("regime32", "phases: the paper's 240/100/520/200 T* (window 100-200)"),
    ("regime48", "grid 48^3 at the paper's phases"),
    ("regime64short", "grid 64^3 at small's phases"),
    ("regime64", "grid 64^3 at the paper's phases"),
    ("regime32n3", "3e5 particles at 32^3 and the paper's phases"),
    ("regime48n3", "3e5 particles at 48^3 and the paper's phases"),
    ("printed", "regime64 at the wall-normal grid the paper prints "
                "(64 x 128 x 64, y+ 0.63, dt* 0.005)"),
)
