# The package sharp_features: it re-exports the extraction (`extract`, `Result`, `Cancelled`
# and the tiled functions) and the point cloud files (`PointReader`, `read_point_cloud`,
# `write_las`); `python3 -m sharp_features INPUT -o OUT.polylines.txt` runs it on a file,
# distributed on a dask cluster if asked (see sharp_features.__main__). Its docstring is the
# extension's.

from ._sharp_features import *  # noqa: F401,F403 (the extension's public names are the package's)
from ._sharp_features import __doc__, __version__  # noqa: F401
from ._point_files import PointReader, read_point_cloud, write_las  # noqa: F401
