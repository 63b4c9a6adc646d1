"""Python helpers of the agglomerationHardSphere project: reading and
writing OpenFOAM case files and the hard-sphere statistics, and rendering
particle fields. Used by the tutorials' set-up and post-processing."""
