"""Design-space exploration: several quantities of a problem at once over a full grid, a Latin hypercube or a
Sobol' sample, up to 10^8 designs, evaluated partition by partition with the engine's sweep in this process or
on Dask, written to Parquet as partitions finish, resumed from the partitions on disk after an interruption.

Dask and pyarrow are imported only by the functions that use them.
"""

from .execution import Execution, execution
from .run import Exploration, explore, plan_exploration
from .sampling import DesignSpace, designs, partition_designs
from .store import read_exploration

__all__ = ["DesignSpace", "Execution", "Exploration", "designs", "execution", "explore", "partition_designs",
           "plan_exploration", "read_exploration"]
