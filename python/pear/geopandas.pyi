# Types of pear.geopandas (docs/python.md, "pear.geopandas"). Options are triangulate_many's.
from typing import Any, Optional, Union

import pandas

def triangulate(data: Union[pandas.Series, pandas.DataFrame], *, geometry: Optional[str] = None,
                **options: Any) -> pandas.DataFrame: ...

# A geopandas.GeoDataFrame (typed as a DataFrame: geopandas ships no types).
def triangle_polygons(data: Union[pandas.Series, pandas.DataFrame], *,
                      geometry: Optional[str] = None, **options: Any) -> pandas.DataFrame: ...
