"""The channel report's pictures: the profiles and the particle picture
(profiles), the configurations' matrix (matrix)."""
