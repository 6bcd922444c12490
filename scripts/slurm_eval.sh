#!/bin/bash
# A simhuman benchmark on a Slurm allocation: one MPI rank per core, episodes sharded by index.
# Submit:   sbatch scripts/slurm_eval.sh            (edit the #SBATCH lines for your cluster)
# Continue: sbatch --export=ALL,RESUME=1 scripts/slurm_eval.sh   (after a node failure or a
#           time-out: runs only the episodes missing from $OUT)
#SBATCH --job-name=simhuman-eval
#SBATCH --nodes=4
#SBATCH --ntasks-per-node=32
#SBATCH --cpus-per-task=1
#SBATCH --time=02:00:00
#SBATCH --output=simhuman-eval-%j.log
set -euo pipefail

SIMHUMAN=${SIMHUMAN:-$HOME/simhuman/build/simhuman}   # the same binary on every node
SUITE=${SUITE:-sit}
EPISODES=${EPISODES:-1000}
SEED=${SEED:-1}
OUT=${OUT:-$HOME/simhuman-runs/eval_${SUITE}_seed${SEED}}   # on a shared file system
MPC_CONFIG=${MPC_CONFIG:-$OUT.mpc.json}

# the MPC on one thread per rank (one rank per core)
if [ ! -f "$MPC_CONFIG" ]; then echo '{"threads": 1}' > "$MPC_CONFIG"; fi
export OMP_NUM_THREADS=1

resume=()
if [ "${RESUME:-0}" = 1 ]; then resume=(--resume); fi
# srun starts the ranks under Slurm's PMI; `mpirun` (Open MPI) works the same inside the job
srun --mpi=pmix "$SIMHUMAN" eval --suite "$SUITE" --episodes "$EPISODES" --seed "$SEED" \
  --config "$MPC_CONFIG" --out "$OUT" "${resume[@]}"
