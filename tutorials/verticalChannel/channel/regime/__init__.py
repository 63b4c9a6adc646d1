"""The regime study of the channel (README.md, 'The regime study'): its
variants, their analysis, the grid trend, the one-shortcut pairs, the
verdict, its table and plots; its command is channel.regime.study."""
