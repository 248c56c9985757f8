"""The pinned lettering font (osifont) and its fontconfig file, shipped with the package."""
