#!/bin/bash
# Data-parallel PPO (DD-PPO style) on a Slurm allocation: every rank steps its own
# environments, gradients are averaged with an allreduce, rank 0 writes the checkpoints.
# Submit:   sbatch scripts/slurm_train.sh
# Continue: sbatch --export=ALL,RESUME=1 scripts/slurm_train.sh  (any rank count: the
#           checkpoint holds nothing rank-specific)
#SBATCH --job-name=simhuman-train
#SBATCH --nodes=2
#SBATCH --ntasks-per-node=32
#SBATCH --cpus-per-task=1
#SBATCH --time=04:00:00
#SBATCH --signal=TERM@120
#SBATCH --output=simhuman-train-%j.log
set -euo pipefail

SIMHUMAN=${SIMHUMAN:-$HOME/simhuman/build/simhuman}
TASK=${TASK:-walk}
STEPS=${STEPS:-200M}
ENVS_PER_RANK=${ENVS_PER_RANK:-64}
SEED=${SEED:-1}
OUT=${OUT:-$HOME/simhuman-runs/train_${TASK}_seed${SEED}}   # on a shared file system
export OMP_NUM_THREADS=1

# Slurm sends SIGTERM 120 s before the time limit: every rank stops at the same iteration
# and rank 0 writes the checkpoint; resubmit with RESUME=1 to continue.
if [ "${RESUME:-0}" = 1 ]; then
  srun --mpi=pmix "$SIMHUMAN" train --resume "$OUT" --steps "$STEPS" --quiet
else
  srun --mpi=pmix "$SIMHUMAN" train --task "$TASK" --steps "$STEPS" --envs "$ENVS_PER_RANK" \
    --threads 1 --seed "$SEED" --out "$OUT" --quiet
fi
