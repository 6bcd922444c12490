#!/usr/bin/env python3
"""The cluster throughput model of docs/SCALING.md, fed from a data-parallel training log.

Usage: scripts/scaling_model.py RUN/log.jsonl [--skip 6] [--alpha-us 5] [--beta-gbps 1]

RUN must be a run of 2 or more ranks (it logs `rank_rollout_s`, every rank's own rollout time,
and the time inside the gradient allreduces). Inputs taken from the log, iterations after the
first `--skip`:
  T1     the no-wait iteration of one rank: its rollout + the update - the waits inside the
         update's allreduces + their transfer time (calls x alpha + bytes / beta)
  sigma  the spread of the ranks' rollout times within one iteration: sd(rank1 - rank0) / sqrt 2
  S, n   allreduce payload per rank and calls per iteration
The model: T(K) = T1 + sigma m(K) + n A(K, S / n), A(K, s) = 2 log2(K) alpha + 2 (K-1)/K s / beta,
where m(K) is the expected maximum of K standard normals; efficiency(K) = T1 / T(K).
"""
import argparse, json, math, statistics


def expected_max_normal(k, samples=200001):
    """E[max of k iid N(0,1)] by numerical integration of 1 - Phi(x)^k."""
    if k == 1:
        return 0.0
    lo, hi = -10.0, 10.0
    h = (hi - lo) / (samples - 1)
    total = 0.0
    for i in range(samples):
        x = lo + i * h
        cdf = 0.5 * (1 + math.erf(x / math.sqrt(2)))
        pdf = math.exp(-0.5 * x * x) / math.sqrt(2 * math.pi)
        total += x * k * pdf * cdf ** (k - 1)
    return total * h


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('log')
    ap.add_argument('--skip', type=int, default=6)
    ap.add_argument('--alpha-us', type=float, default=5.0)
    ap.add_argument('--beta-gbps', type=float, default=1.0)
    a = ap.parse_args()
    rows = [json.loads(l) for l in open(a.log)]
    # the iterations run on 2 or more ranks (a run may have resumed on another rank count)
    rows = [r for r in rows if r['iteration'] >= a.skip and len(r.get('rank_rollout_s', [])) >= 2]
    if not rows:
        raise SystemExit(a.log + ': no iteration after iteration %d ran on 2 or more ranks with '
                         'rank_rollout_s logged (mpirun -n 2 simhuman train ...)' % a.skip)
    alpha, beta = a.alpha_us * 1e-6, a.beta_gbps * 1e9
    calls = statistics.mean(r['allreduce_calls'] for r in rows)
    size = statistics.mean(r['allreduce_bytes'] for r in rows)
    rollout = statistics.mean(r['rank_rollout_s'][0] for r in rows)
    update = statistics.mean(r['update_s'] for r in rows)
    inside = statistics.mean(r['allreduce_s'] for r in rows)
    sync = statistics.mean(r['sync_s'] for r in rows)
    iteration = statistics.mean(r['collect_s'] + r['update_s'] for r in rows)
    diffs = [r['rank_rollout_s'][1] - r['rank_rollout_s'][0] for r in rows]
    sigma = statistics.stdev(diffs) / math.sqrt(2)

    def allreduce(k, s):
        return 0.0 if k == 1 else 2 * math.log2(k) * alpha + 2 * (k - 1) / k * s / beta

    t1 = rollout + update - inside + calls * allreduce(2, size / calls)
    print('%s: %d iterations; iteration %.3f s, rank 0 rollout %.3f s, update %.3f s' %
          (a.log, len(rows), iteration, rollout, update))
    print('  inside the gradient allreduces %.4f s (%.2f %% of the iteration), waiting after '
          'the rollout %.4f s (%.2f %%)' % (inside, 100 * inside / iteration, sync,
                                           100 * sync / iteration))
    print('  T1 %.3f s, sigma %.4f s (%.1f %% of the rollout), %d allreduces of %.0f KB' %
          (t1, sigma, 100 * sigma / rollout, round(calls), size / calls / 1e3))
    t2 = t1 + calls * allreduce(2, size / calls) + sigma * expected_max_normal(2, 20001)
    print('  check at K = 2: modelled %.3f s per iteration, measured %.3f s (%+.1f %%)' %
          (t2, iteration, 100 * (t2 - iteration) / iteration))
    print('  K      C(K)     W(K)     T(K)   efficiency')
    for k in (1, 2, 8, 16, 64, 128, 256):
        c = calls * allreduce(k, size / calls)
        w = sigma * expected_max_normal(k, 20001)
        t = t1 + c + w
        print('  %-4d %6.1f ms %6.1f ms %7.3f s %6.1f %%' % (k, 1e3 * c, 1e3 * w, t, 100 * t1 / t))


if __name__ == '__main__':
    main()
