#!/bin/bash
# A tribo sweep on a Slurm cluster: one MPI rank per node, each running as many points at once as
# its node has cores (one OpenMP thread per point). Rank 0 hands out points as ranks free up and
# alone writes results.csv / sweep.json; the output folder must be on a file system every node sees
# (home or a parallel scratch, not node-local /tmp). Submit with
#   sbatch examples/sweep-slurm.sh examples/roughness-study.toml /scratch/$USER/roughness-study
# Resubmitting the same command after a time-out or a node failure resumes: finished points are
# kept, the rest run (a changed spec or base config is refused).
#SBATCH --job-name=tribo-sweep
#SBATCH --nodes=4
#SBATCH --ntasks-per-node=1
#SBATCH --cpus-per-task=32
#SBATCH --time=24:00:00
#SBATCH --output=tribo-sweep-%j.log
set -euo pipefail

SPEC=${1:?usage: sbatch sweep-slurm.sh SPEC.toml OUT_DIR}
OUT=${2:?usage: sbatch sweep-slurm.sh SPEC.toml OUT_DIR}
TRIBO=${TRIBO:-tribo}   # the tribo executable (e.g. build/apps/tribo), the same on every node

# Leave [sweep] jobs unset (0) in the spec: each rank then runs as many points at once as its node
# has cores divided by the ranks on that node (here cpus-per-task points per node).
export OMP_NUM_THREADS=1

# mpirun inside the allocation starts one rank per task; Open MPI sets OMPI_COMM_WORLD_SIZE, which
# switches `tribo sweep` to MPI mode. With `srun` (PMIx) instead, add --mpi:
#   srun --mpi=pmix "$TRIBO" sweep "$SPEC" --out "$OUT" --mpi
# --bind-to none: a rank's points are child processes and must be free to use all of its cores.
mpirun --bind-to none --map-by ppr:1:node "$TRIBO" sweep "$SPEC" --out "$OUT"
