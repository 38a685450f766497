#!/usr/bin/env python3
"""Compare Sightline's scenario dynamics with ViZDoom's (issue 40, point 5).

For each single-player ViZDoom scenario this runs N episodes of the same seeded
random policy in the `vizdoom` package (1.3.2) and in Sightline
(`sightline autoplay SCENARIO.cfg --json --episodes N --seed S --policy random`),
and prints a Markdown table of episode length (tics) and total reward on both
sides with Welch's t-test on the means and, for lengths, a two-sample
Kolmogorov-Smirnov test on the distributions.

The policy, on both sides: each tic, choose uniformly one of the .cfg's
available buttons pressed alone, or no button at all (k + 1 actions for k
buttons), from Python's `random.Random(seed)` for ViZDoom; frame skip 1. The
two sides do not share a random stream (Sightline draws its own from the
seed), so the comparison is between distributions, never episode by episode.

ViZDoom's side is seeded with `DoomGame.set_seed(seed)` once before `init`;
each `new_episode` then draws the map's seed from that instance generator
(`DoomController::getNextDoomSeed`), so a rerun with the same seed repeats.

What an episode reports, on the ViZDoom side:
  tics     the number of `make_action(action, 1)` calls before
           `is_episode_finished()`: the tics the policy played, after the
           .cfg's `episode_start_time` (those tics are not counted and their
           living reward is dropped, `DoomGame::resetState`).
  reward   `get_total_reward()`: the change in ACS global 0 (fixed point,
           /65536) plus `living_reward` per played tic, minus
           `death_penalty` if the player died.
  end      "death" if `is_player_dead()`, "timeout" if
           `is_episode_timeout_reached()`, else "exit" (the map ended,
           e.g. ACS `Exit_Normal`).

Usage (from the repository root):

  python3 scripts/vizdoom-compare.py --out docs/vizdoom-compare.md
  python3 scripts/vizdoom-compare.py --vizdoom-only \
      --vizdoom-json docs/vizdoom-reference.json
  python3 scripts/vizdoom-compare.py --only basic,take_cover --episodes 50
  python3 scripts/vizdoom-compare.py --speed --out docs/python-speed.md

`--speed` measures steps per second of both Python packages instead (the
`vizdoom` package and Sightline's, installed in the same Python; see
scripts/vizdoom_speed.py).

`--vizdoom-json FILE` caches ViZDoom's side: scenarios already in FILE with
the same seed, episode count and policy are read from it, the rest are run and
added (the file is replaced atomically). Needs numpy and vizdoom; uses scipy's
tests when it is installed and the same tests written out below otherwise.
"""

import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

SCENARIOS = [
    "basic",
    "simpler_basic",
    "rocket_basic",
    "basic_audio",
    "basic_notifications",
    "defend_the_center",
    "defend_the_line",
    "health_gathering",
    "health_gathering_supreme",
    "my_way_home",
    "deadly_corridor",
    "predict_position",
    "take_cover",
]

POLICY = "random: uniform over each available button alone and no button, per tic, frame skip 1"


# ---------------------------------------------------------------- statistics
#
# Welch's t-test needs Student's t CDF, which is the regularized incomplete
# beta function; the KS test needs the Kolmogorov distribution. Both are
# written out so the script runs where scipy is not installed; where it is,
# scipy's versions are used (its KS test is exact for small samples).


def _betacf(a, b, x):
    """Continued fraction of the incomplete beta function (modified Lentz)."""
    tiny = 1e-300
    qab, qap, qam = a + b, a + 1.0, a - 1.0
    c, d = 1.0, 1.0 - qab * x / qap
    d = 1.0 / (d if abs(d) > tiny else tiny)
    h = d
    for m in range(1, 1000):
        m2 = 2 * m
        aa = m * (b - m) * x / ((qam + m2) * (a + m2))
        d = 1.0 + aa * d
        d = 1.0 / (d if abs(d) > tiny else tiny)
        c = 1.0 + aa / c
        c = c if abs(c) > tiny else tiny
        h *= d * c
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2))
        d = 1.0 + aa * d
        d = 1.0 / (d if abs(d) > tiny else tiny)
        c = 1.0 + aa / c
        c = c if abs(c) > tiny else tiny
        de = d * c
        h *= de
        if abs(de - 1.0) < 1e-15:
            break
    return h


def _betainc(a, b, x):
    """Regularized incomplete beta I_x(a, b)."""
    if x <= 0.0:
        return 0.0
    if x >= 1.0:
        return 1.0
    lbt = math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) + a * math.log(x) + b * math.log1p(-x)
    if x < (a + 1.0) / (a + b + 2.0):
        return math.exp(lbt) * _betacf(a, b, x) / a
    return 1.0 - math.exp(lbt) * _betacf(b, a, 1.0 - x) / b


def welch_p(xs, ys):
    """Two-sided p-value of Welch's t-test; None when it is undefined."""
    n1, n2 = len(xs), len(ys)
    if n1 < 2 or n2 < 2:
        return None
    m1, m2 = sum(xs) / n1, sum(ys) / n2
    v1 = sum((x - m1) ** 2 for x in xs) / (n1 - 1)
    v2 = sum((y - m2) ** 2 for y in ys) / (n2 - 1)
    se2 = v1 / n1 + v2 / n2
    if se2 == 0.0:
        # Both samples constant: equal means agree perfectly, else they differ.
        return 1.0 if m1 == m2 else 0.0
    t = (m1 - m2) / math.sqrt(se2)
    df = se2 ** 2 / ((v1 / n1) ** 2 / (n1 - 1) + (v2 / n2) ** 2 / (n2 - 1))
    return _betainc(df / 2.0, 0.5, df / (df + t * t))


def ks_p(xs, ys):
    """Two-sided p-value of the two-sample Kolmogorov-Smirnov test
    (asymptotic Kolmogorov distribution with Stephens' small-sample
    correction, as in Numerical Recipes' kstwo)."""
    n1, n2 = len(xs), len(ys)
    if n1 == 0 or n2 == 0:
        return None
    a, b = sorted(xs), sorted(ys)
    i = j = 0
    d = 0.0
    while i < n1 and j < n2:
        v = min(a[i], b[j])
        while i < n1 and a[i] == v:
            i += 1
        while j < n2 and b[j] == v:
            j += 1
        d = max(d, abs(i / n1 - j / n2))
    en = math.sqrt(n1 * n2 / (n1 + n2))
    lam = (en + 0.12 + 0.11 / en) * d
    if lam < 1e-3:
        return 1.0
    s, sign = 0.0, 1.0
    for k in range(1, 101):
        term = sign * 2.0 * math.exp(-2.0 * k * k * lam * lam)
        s += term
        if abs(term) < 1e-12:
            break
        sign = -sign
    return min(1.0, max(0.0, s))


try:
    import scipy.stats as _stats

    def welch_p(xs, ys, _own=welch_p):  # noqa: F811
        if len(xs) < 2 or len(ys) < 2:
            return None
        p = _stats.ttest_ind(xs, ys, equal_var=False).pvalue
        return _own(xs, ys) if p != p else float(p)  # NaN: constant samples

    def ks_p(xs, ys):  # noqa: F811
        if not xs or not ys:
            return None
        return float(_stats.ks_2samp(xs, ys).pvalue)

    STATS = "scipy " + __import__("scipy").__version__
except ImportError:
    STATS = "own implementation (scipy not installed)"


def mean_sd(xs):
    if not xs:
        return float("nan"), float("nan")
    m = sum(xs) / len(xs)
    if len(xs) < 2:
        return m, 0.0
    return m, math.sqrt(sum((x - m) ** 2 for x in xs) / (len(xs) - 1))


# ---------------------------------------------------------------- ViZDoom side


def run_vizdoom(cfg, episodes, seed, log):
    import vizdoom as vzd

    game = vzd.DoomGame()
    game.load_config(cfg)
    # Nothing here changes the simulation: no window, smallest screen, no
    # sound output (monsters hear the player through P_NoiseAlert, which is
    # game logic, not audio), and no audio buffer, which needs a device.
    game.set_window_visible(False)
    game.set_mode(vzd.Mode.PLAYER)
    game.set_screen_resolution(vzd.ScreenResolution.RES_160X120)
    game.set_sound_enabled(False)
    game.set_audio_buffer_enabled(False)
    game.set_seed(seed)
    # ViZDoom writes its engine settings to _vizdoom.ini in the working
    # folder unless told otherwise; keep it out of the repository.
    ini_dir = tempfile.mkdtemp(prefix="vizdoom-compare-")
    game.set_doom_config_path(os.path.join(ini_dir, "_vizdoom.ini"))
    game.init()
    buttons = [str(b).split(".")[-1] for b in game.get_available_buttons()]
    k = len(buttons)
    actions = [[1.0 if i == j else 0.0 for i in range(k)] for j in range(k)]
    actions.append([0.0] * k)
    rng = random.Random(seed)
    info = {
        "buttons": buttons,
        "episode_timeout": game.get_episode_timeout(),
        "episode_start_time": game.get_episode_start_time(),
        "living_reward": game.get_living_reward(),
        "death_penalty": game.get_death_penalty(),
    }
    out = []
    start = time.time()
    for e in range(episodes):
        game.new_episode()
        tics = 0
        while not game.is_episode_finished():
            game.make_action(rng.choice(actions), 1)
            tics += 1
        dead = bool(game.is_player_dead())
        if dead:
            end = "death"
        elif game.is_episode_timeout_reached():
            end = "timeout"
        else:
            end = "exit"
        out.append(
            {
                "tics": tics,
                "reward": game.get_total_reward(),
                "dead": dead,
                "end": end,
                "episode_time": game.get_episode_time(),
            }
        )
    seconds = time.time() - start
    game.close()
    shutil.rmtree(ini_dir, ignore_errors=True)
    log(f"vizdoom {os.path.basename(cfg)}: {episodes} episodes in {seconds:.1f} s")
    info["seconds"] = round(seconds, 2)
    info["episodes"] = out
    return info


def load_cache(path):
    if not path or not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def write_atomic(path, text):
    """Write via a temporary file in the same folder and rename, so a failed
    run never leaves a half-written or clobbered file."""
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=".tmp-", dir=folder)
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


# ---------------------------------------------------------------- Sightline side


def run_sightline(binary, cfg, episodes, seed, log):
    """Returns (episodes list, None) or (None, error text)."""
    cmd = [binary, "autoplay", cfg, "--json", "--episodes", str(episodes), "--seed", str(seed), "--policy", "random"]
    start = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True)
    except OSError as e:
        return None, f"could not run {binary}: {e}"
    if p.returncode != 0:
        lines = p.stderr.strip().splitlines() or ["(no stderr)"]
        # clap and anyhow put the reason on the line starting with "error";
        # otherwise the last line is the most specific.
        why = next((l for l in lines if l.lower().startswith("error")), lines[-1])
        return None, f"exit status {p.returncode}: {why.strip()}"
    try:
        doc = json.loads(p.stdout)
        eps = doc["episodes"]
        for ep in eps:
            float(ep["tics"]), float(ep["reward"])
    except (ValueError, KeyError, TypeError) as e:
        return None, f"unreadable JSON ({e})"
    log(f"sightline {os.path.basename(cfg)}: {len(eps)} episodes in {time.time() - start:.1f} s")
    return eps, None


# ---------------------------------------------------------------- report


def fmt_ms(xs, digits):
    if not xs:
        return "–"
    m, s = mean_sd(xs)
    return f"{m:.{digits}f} ± {s:.{digits}f}"


def fmt_p(p):
    if p is None:
        return "–"
    return f"{p:.3g}" if p >= 1e-4 else "<1e-4"


def end_shares(eps):
    """'death/timeout/exit' shares in percent; Sightline's side gives only
    `dead`, so its timeout and exit are told apart by `end` when present."""
    if not eps:
        return "–"
    n = len(eps)
    dead = sum(1 for e in eps if e.get("dead"))
    if all("end" in e for e in eps):
        to = sum(1 for e in eps if e["end"] == "timeout")
        ex = sum(1 for e in eps if e["end"] == "exit")
        return f"{100 * dead / n:.0f}/{100 * to / n:.0f}/{100 * ex / n:.0f}"
    return f"{100 * dead / n:.0f}/–/–"


def report(rows, args, errors):
    lines = [
        "# ViZDoom vs Sightline: random-policy dynamics",
        "",
        f"{args.episodes} episodes per scenario, seed {args.seed}; policy: {POLICY}. "
        f"Tests: Welch's t-test on the means, two-sample Kolmogorov-Smirnov on the lengths "
        f"({STATS}). Ends are death/timeout/exit in percent of episodes. A p-value below 0.01 "
        f"is a difference beyond sampling error; with 13 scenarios and three tests each, about "
        f"one run in three shows one p < 0.01 by chance.",
        "",
        "| scenario | episodes vz/sl | tics ViZDoom | tics Sightline | p (t) | p (KS) "
        "| reward ViZDoom | reward Sightline | p (t) | ends ViZDoom | ends Sightline |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for name, vz, sl in rows:
        vt = [e["tics"] for e in vz]
        vr = [e["reward"] for e in vz]
        st = [e["tics"] for e in sl] if sl else []
        sr = [e["reward"] for e in sl] if sl else []
        lines.append(
            f"| {name} | {len(vt)}/{len(st) if sl else '–'} | {fmt_ms(vt, 1)} | {fmt_ms(st, 1)} "
            f"| {fmt_p(welch_p(vt, st) if sl else None)} | {fmt_p(ks_p(vt, st) if sl else None)} "
            f"| {fmt_ms(vr, 2)} | {fmt_ms(sr, 2)} | {fmt_p(welch_p(vr, sr) if sl else None)} "
            f"| {end_shares(vz)} | {end_shares(sl) if sl else '–'} |"
        )
    lines += [
        "",
        "Made by `scripts/vizdoom-compare.py` (ViZDoom's side cached in `docs/vizdoom-reference.json`); "
        "what the differences come from is in ARCHITECTURE.md, \"ZDoom-format scenarios\".",
    ]
    if errors:
        lines += ["", "Sightline's side failed for:", ""]
        lines += [f"- {name}: {err}" for name, err in errors]
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--episodes", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--scenarios", help="folder of the .cfg and .wad files (default: the vizdoom package's)")
    ap.add_argument("--only", help="comma-separated scenario names")
    ap.add_argument("--sightline", default="target/release/sightline", help="the sightline binary")
    ap.add_argument("--vizdoom-only", action="store_true", help="run only ViZDoom's side")
    ap.add_argument("--vizdoom-json", help="cache of ViZDoom's side (read, completed and rewritten)")
    ap.add_argument("--out", help="also write the Markdown table to this file")
    ap.add_argument(
        "--speed",
        action="store_true",
        help="measure steps per second instead (scripts/vizdoom_speed.py): both packages in this Python",
    )
    ap.add_argument("--speed-steps", type=int, default=2000, help="steps per round with --speed")
    ap.add_argument("--speed-rounds", type=int, default=5, help="rounds per cell with --speed")
    args = ap.parse_args()

    def log(msg):
        print(msg, file=sys.stderr, flush=True)

    if args.speed:
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import vizdoom_speed

        folder = args.scenarios
        if folder is None:
            import vizdoom as vzd

            folder = vzd.scenarios_path
        names = args.only.split(",") if args.only else ["basic", "deadly_corridor"]
        rows = vizdoom_speed.measure(folder, names, args.speed_steps, args.speed_rounds, log)
        text = vizdoom_speed.table(rows, args.speed_steps, args.speed_rounds)
        sys.stdout.write(text)
        if args.out:
            write_atomic(args.out, text)
        return

    names = SCENARIOS
    if args.only:
        names = [n.strip() for n in args.only.split(",") if n.strip()]
        unknown = [n for n in names if n not in SCENARIOS]
        if unknown:
            ap.error(f"not a single-player scenario: {', '.join(unknown)} (known: {', '.join(SCENARIOS)})")

    folder = args.scenarios
    if folder is None:
        try:
            import vizdoom as vzd
        except ImportError:
            ap.error("the vizdoom package is not installed (pip install vizdoom==1.3.2); or give --scenarios")
        folder = vzd.scenarios_path

    cache = load_cache(args.vizdoom_json)
    key = {"seed": args.seed, "episodes": args.episodes, "policy": POLICY}
    if cache is None or any(cache.get(k) != v for k, v in key.items()):
        if cache is not None:
            log(f"{args.vizdoom_json}: other seed, episode count or policy; running ViZDoom again")
        import vizdoom as vzd

        cache = dict(key, vizdoom=vzd.__version__, scenarios={})

    rows, errors = [], []
    for name in names:
        cfg = os.path.join(folder, name + ".cfg")
        if not os.path.exists(cfg):
            log(f"{cfg}: no such file")
            sys.exit(1)
        if name not in cache["scenarios"]:
            cache["scenarios"][name] = run_vizdoom(cfg, args.episodes, args.seed, log)
            if args.vizdoom_json:
                write_atomic(args.vizdoom_json, json.dumps(cache, indent=1) + "\n")
        vz = cache["scenarios"][name]["episodes"]
        sl = None
        if not args.vizdoom_only:
            sl, err = run_sightline(args.sightline, cfg, args.episodes, args.seed, log)
            if err:
                log(f"sightline {name}: {err}")
                errors.append((name, err))
        rows.append((name, vz, sl))

    text = report(rows, args, errors)
    sys.stdout.write(text)
    if args.out:
        write_atomic(args.out, text)
    sys.exit(1 if errors else 0)


if __name__ == "__main__":
    main()
