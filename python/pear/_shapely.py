"""pear.shapely_triangles: triangles as shapely Polygons, with no geopandas."""
import numpy as np

from . import _pear


def shapely_triangles(points, triangles):
    """Each triangle as a shapely Polygon (counterclockwise, its ring closed), in the order of
    triangles: a list of M Polygons. points: (N, 2) coordinates; triangles: (M, 3) indices
    into them (checked: an index out of range raises ValueError). For a shapely polygon:
    ``pear.shapely_triangles(*pear.triangulate_points(polygon))``."""
    values = _pear.triangles_wkb(points, triangles)
    import shapely
    from_wkb = getattr(shapely, "from_wkb", None)  # shapely 2: one call over the array
    if from_wkb is not None:
        return list(from_wkb(np.array(values, dtype=object)))
    from shapely import wkb
    return [wkb.loads(value) for value in values]
