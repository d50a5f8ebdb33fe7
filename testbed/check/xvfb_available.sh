# Sourced by the testbed's tests: exits 77 (skipped) when no X server can be started here.
if ! command -v xvfb-run >/dev/null; then
  echo "skipped: xvfb-run is not installed (apt-get install xvfb xauth), so no X server for the testbed"
  exit 77
fi
if ! xvfb-run -a true 2>/dev/null; then
  echo "skipped: xvfb-run cannot start an X server here"
  exit 77
fi
