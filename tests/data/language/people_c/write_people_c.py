"""Independent command set "people_c" for simhuman's offline planner (held out).

Written by a helper session (corpus writer C) on 2026-11-28.  Sources: the UniHSI paper
(ICLR 2024, Section 3 and Tables 5-9), docs/FORMATS.md (plan format, built-in scenes,
the stated plan conventions), the conventions sections of people_a/README.md and
people_b/README.md, and the helper functions of people_b/write_people_b.py (lines 1-141:
the pair conventions).  Every expectation below was written by hand from those conventions
BEFORE anything was run; the planner sources, the main corpus and the commands of sets A
and B were not read, and no planner binary was run.

Imagined users (new, not those of A and B): a film director giving blocking notes, a
voice-assistant user (transcribed speech: "um", "uh", no punctuation, run-ons), an
elderly-care nurse, a teenager with slang and chat spellings, a stage-play script with
stage directions in brackets, a UX tester writing numbered test steps, someone typing
lowercase shorthand, a British English speaker, and people who add reasons ("because
you're tired"), time words ("for a minute"), adverbs ("slowly"), negations that still
leave one clear action, ids and pronouns referring back ("sit on it").

Run:  python3 write_people_c.py > people_c.jsonl
"""
import json

LINES = []


def add(scene, expect, *commands):
    for c in commands:
        LINES.append({"scene": scene, "command": c, "expect": expect})


def ambiguous(scene, *commands):
    for c in commands:
        LINES.append({"scene": scene, "command": c, "expect_ambiguous": True})


def error(scene, *commands):
    for c in commands:
        LINES.append({"scene": scene, "command": c, "expect_error": True})


# ---------------------------------------------------------------- helpers
# The plan conventions (same pairs as set B's helpers).  Each returns a LIST of
# "object|part|joint|contact|direction" strings; a step is built with "+".
def GC(o, side="front"):
    """Get close / walk to o; also 'stand up' from o (front)."""
    return [f"{o}|none|none|none|{side}"]


def SIT(o):
    return [f"{o}|seat surface|pelvis|contact|up"]


def SITBED(o):
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|not contact|up"]


def LIE(o):
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|contact|up"]


# seated poses (joined to the seat pair)
def HANDARM1(o, s):
    return [f"{o}|{s} arm|{s} hand|contact|up"]


def HANDARM2(o):
    return [f"{o}|left arm|left hand|contact|none", f"{o}|right arm|right hand|contact|none"]


def HANDOFF(o):
    return [f"{o}|left arm|left hand|not contact|none", f"{o}|right arm|right hand|not contact|none"]


def ELBOW1(o, s):
    return [f"{o}|{s} arm|{s} elbow|contact|up"]


def ELBOW2(o):
    return [f"{o}|left arm|left elbow|contact|none", f"{o}|right arm|right elbow|contact|none"]


def KNEE1(o, s):
    return [f"{o}|{s} knee|{s} hand|contact|up"]


def KNEE2(o):
    return [f"{o}|left knee|left hand|contact|none", f"{o}|right knee|right hand|contact|none"]


def STOM(o, *sides):
    return [f"{o}|pelvis|{s} hand|contact|none" for s in sides]


def FOOT(o, foot, knee):
    return [f"{o}|{knee} knee|{foot} foot|contact|none"]


def LEANF(o):
    return [f"{o}|back surface|torso|not contact|none"]


def LEANB(o):
    return [f"{o}|back surface|torso|contact|none"]


# lying poses (joined to the lying pairs)
def KNEEUP(o, *sides):
    return [f"{o}|mattress|{s} knee|not contact|none" for s in sides]


def HPILLOW(o, *sides):
    return [f"{o}|pillow|{s} hand|contact|none" for s in sides]


def SIDE(o, side):
    """On the left side lifts the right shoulder, and vice versa."""
    shoulder = "right" if side == "left" else "left"
    return [f"{o}|mattress|{shoulder} shoulder|not contact|none"]


def FOOTLIE(o, foot, knee):
    return [f"{o}|{knee} knee|{foot} foot|contact|up"]


def HEADUP(o):
    """Replaces LIE: pelvis on the mattress, head off the pillow."""
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|not contact|none"]


# reaching
def REACH(o, part, d, *hands):
    hands = hands or ("right",)
    return [f"{o}|{part}|{h} hand|contact|{d}" for h in hands]


def SEATREACH(o, part, *hands):
    """Touch while seated (UniHSI Table 7): hands have direction none."""
    hands = hands or ("left", "right")
    return [f"{o}|{part}|{h} hand|contact|none" for h in hands]


def TAB(a, b, part, d, hand="right"):
    """Pick and place: grasp step, then grasp + object-object pair."""
    grasp = [f"{a}|body|{hand} hand|contact|none"]
    return [grasp, grasp + [f"{b}|{part}|@{a}:body|contact|{d}"]]


def GRASP(a, hand="right"):
    return [f"{a}|body|{hand} hand|contact|none"]


# ================================================================ sit_demo
# chair000 (plain chair, no arms) at the origin; the human stands 0.4 m in front of
# the seat: within 1 m, so no implied get-close step.
S = "sit_demo"
C = "chair000"
add(S, [SIT(C)],
    "um can you like sit down on the chair",
    "[sits in the chair]",
    "sit down slowly because you're tired",
    "let's get you sitting down in the chair, nice and slow")
add(S, [SIT(C), GC(C)],
    "(She sits, then rises.)",
    "sit down in the chair for me, that's it, now stand up again")
add(S, [GC(C)],
    "walk up to the chair")
add(S, [SIT(C) + KNEE1(C, "left")],
    "sit on the chair with your left hand resting on your left knee")
add(S, [SIT(C), SIT(C) + LEANF(C)],
    "have a sit down, then lean forwards",
    "sit chair, lean fwd")
add(S, [SIT(C) + LEANB(C)],
    "sit down and rest your back against the backrest")
add(S, [SIT(C), SIT(C) + LEANB(C)],
    "ok on action you sit down in the chair and then lean back")
add(S, [SIT(C), SIT(C) + FOOT(C, "right", "left"), GC(C)],
    "sit, cross your right leg over your left, then get up")
add(S, [SIT(C) + LEANF(C), SIT(C) + LEANB(C)],
    "sit and lean forward, then sit back")
add(S, [SIT(C) + STOM(C, "left", "right")],
    "sit down and put your hands on your belly")
add(S, [REACH(C, "back surface", "front", "left")],
    "touch the backrest with your left hand")
error(S,
      "lie down on the bed for a bit",
      "sit in the chair and rest your arms on the armrests",
      "sit on the couch")

# ================================================================ living_room
# chair000 (0.95, 0) facing the table001 (2.2, 0) with laptop002 on it; bed003 (4.2, -2.5)
# yaw 90 (front towards +y); armchair004 (0, 2.5); sofa005 (-2.5, 0); stool006 (-0.5, -2.5).
# The human starts at (4.0, -1.35), 0.4 m from the bed: lying or sitting on the bed needs
# no get-close step; every other object is more than 1 m away.
L = "living_room"
CH, TB, LT, BD, AC, SF, ST = ("chair000", "table001", "laptop002", "bed003",
                              "armchair004", "sofa005", "stool006")
add(L, [GC(AC), SIT(AC)],
    "[crosses to the armchair and sits]",
    "don't go to the sofa, sit in the armchair instead",
    "see the armchair? sit in it")
add(L, [GC(SF), SIT(SF)],
    "go to the sofa and sit on it",
    "pop yourself down on the settee",
    "yo go sit on the couch fr")
add(L, [LIE(BD)],
    "have a lie-down on the bed because it's late")
add(L, [LIE(BD) + KNEEUP(BD, "left", "right")],
    "hey can you um lie down on the bed and uh bend your knees")
add(L, [LIE(BD), LIE(BD) + SIDE(BD, "right")],
    "lie on the bed, then roll onto your right side")
add(L, [LIE(BD), GC(BD), GC(SF), SIT(SF)],
    "crash on the bed for a bit, then get up and go sit on the couch")
add(L, [GC(AC), SIT(AC) + ELBOW2(AC)],
    "sit in the armchair with both elbows on the armrests")
add(L, [GC(AC), SIT(AC) + HANDARM2(AC)],
    "settle into the armchair, hands resting on the armrests",
    "okay go to the armchair sit down and put both hands on the armrests")
add(L, [GC(AC), SIT(AC), SIT(AC) + ELBOW1(AC, "left")],
    "go over to the armchair, sit down, and rest your left elbow on the left armrest")
add(L, [GC(AC), SIT(AC), SIT(AC) + LEANB(AC)],
    "from the top: walk to the armchair, sit, lean back")
add(L, [GC(SF), SIT(SF) + ELBOW1(SF, "right")],
    "sit down on the sofa with your right elbow on the armrest")
add(L, [GC(SF), SIT(SF), SIT(SF) + KNEE2(SF)],
    "okay um go over to the couch and uh sit down and then put your hands on your knees")
add(L, [GC(SF), SIT(SF), GC(SF), GC(AC)],
    "sit on the sofa, then move over to the armchair")
add(L, [GC(TB)],
    "nip over to the table")
add(L, [GC(BD, "left")],
    "walk round to the left side of the bed")
add(L, [GC(ST), SIT(ST)],
    "Step 1: walk to the stool. Step 2: sit on it.",
    "sit on the little stool for a minute")
add(L, [GC(CH), SIT(CH), SIT(CH) + SEATREACH(LT, "keyboard")],
    "sit on the chair at the table, then start typing on the laptop")
add(L, [GC(TB), SIT(CH)],
    "walk to the table, then sit on the chair")
add(L, [SITBED(BD), LIE(BD)],
    "sit on the edge of the bed, then lie back")
add(L, [LIE(BD), HEADUP(BD)],
    "lie on the bed, then lift your head up a bit")
add(L, [LIE(BD) + FOOTLIE(BD, "left", "right")],
    "lie on the bed, left foot on your right knee")
add(L, [GC(TB), REACH(TB, "board", "up", "left", "right")],
    "place your hands on the table")
ambiguous(L,
          "take a seat",
          "uh put your elbows on the armrests",
          "touch the backrest",
          "cross your legs")
error(L,
      "sit on the table",
      "turn on the telly",
      "put the laptop on the bed")

# ================================================================ office
# table000 (1.8, 0) yaw 180 with laptop001 on it; chair002 (0.8, 0) facing the table,
# 0.94 m from the human at (0, -1): no get-close before sitting on it; high_stool003
# (1.0, 1.8) and box004 (2.0, -1.6) are more than 1 m away.
O = "office"
OT, OL, OC, OH, OB = "table000", "laptop001", "chair002", "high_stool003", "box004"
add(O, [SIT(OC)],
    "sit on chair002",
    "sit at the desk because you have work to do")
add(O, [SIT(OC), SIT(OC) + SEATREACH(OL, "keyboard")],
    "sit in the chair, then type on the laptop for a while")
add(O, [SIT(OC) + SEATREACH(OL, "keyboard")],
    "take a seat on the chair with both hands resting on the laptop keys")
add(O, [SIT(OC) + SEATREACH(OT, "board")],
    "sit on the chair, both hands on the desk")
add(O, [SIT(OC), SIT(OC) + LEANF(OC)],
    "sit at the desk. lean forward.")
add(O, [SIT(OC) + LEANB(OC)],
    "lean back in the chair for a bit")
add(O, [GC(OH), SIT(OH)],
    "walk over to the bar stool and hop on",
    "sit on the tall stool")
add(O, [GC(OH), SIT(OH) + KNEE2(OH)],
    "sit on the high stool and rest your hands on your knees")
add(O, [GC(OB)],
    "wander over to the box slowly")
add(O, [SIT(OC), GC(OC), GC(OB)],
    "sit at the desk, then get up and go to the box")
add(O, [GC(OB), REACH(OB, "top", "up", "left")],
    "put your left hand on the box")
add(O, [GC(OB), GC(OC), SIT(OC)],
    "go to the box, then sit on the chair")
add(O, [GC(OT, "right")],
    "go to the right side of the desk")
add(O, [GC(OT), REACH(OT, "board", "up", "left", "right")],
    "walk up to the desk and put both hands flat on it")
ambiguous(O,
          "have a seat for a sec",
          "um sit down")
error(O,
      "lie down for a bit",
      "sit on the desk",
      "go to the window")

# ================================================================ bedroom
# bed000 (2.5, 0) yaw 180 (front towards the human), stool001 (2.9, 1.5) next to it,
# chair002 (0, 2.2) yaw -90, box003 (-1.2, -1.5); the human at (0, 0): every object is
# more than 1 m away.
B = "bedroom"
BB, BS, BC, BX = "bed000", "stool001", "chair002", "box003"
add(B, [GC(BB), LIE(BB)],
    "(lies down on the bed)",
    "lie on the bed because you need a nap")
add(B, [GC(BB), SITBED(BB), LIE(BB)],
    "sit on the edge of the bed and then lie down")
add(B, [GC(BB), SITBED(BB), LIE(BB) + HPILLOW(BB, "left", "right")],
    "sit on the bed, then lie down and put your hands on the pillow")
add(B, [GC(BB), LIE(BB) + SIDE(BB, "left")],
    "lie on your left side on the bed")
add(B, [GC(BB), LIE(BB), LIE(BB) + KNEEUP(BB, "left")],
    "lie on the bed, then bend your left knee")
add(B, [GC(BB), LIE(BB) + KNEEUP(BB, "left", "right")],
    "lie down with both knees up")
add(B, [GC(BB), LIE(BB), HEADUP(BB)],
    "lie down on the bed, lift your head off the pillow")
add(B, [GC(BB), HEADUP(BB)],
    "lie on the bed but keep your head off the pillow")
add(B, [GC(BB), LIE(BB) + FOOTLIE(BB, "right", "left")],
    "get into bed and put your right foot on your left knee")
add(B, [GC(BB), LIE(BB), GC(BB), GC(BS), SIT(BS)],
    "lie on the bed and then sit on the stool")
add(B, [GC(BB), LIE(BB), GC(BB), GC(BC), SIT(BC) + KNEE2(BC)],
    "lie down on the bed, then get up and sit in the chair with your hands on your knees")
add(B, [GC(BS), SIT(BS)],
    "sit on the stool, not the chair")
add(B, [GC(BC), SIT(BC) + LEANB(BC)],
    "sit in the chair and lean back")
add(B, [GC(BX), REACH(BX, "top", "up")],
    "walk to the box and touch it")
add(B, [GC(BB), REACH(BB, "mattress", "up", "left")],
    "touch the mattress with your left hand")
ambiguous(B,
          "take a seat please",
          "sit with your hands on your knees")
error(B,
      "sit on the sofa",
      "check your email on the laptop",
      "sit on the stool and lean back")

# ================================================================ tabletop_demo
# table000 (1.0, 0) yaw 180; on it box001 red, box002 green, box003 blue, box004 yellow
# (flat), cylinder005 blue, sphere006 green; the human at (0.2, 0), within 1 m of all.
T = "tabletop_demo"
TT = "table000"
RED, GREEN, BLUE, YEL, CYL, BALL = ("box001", "box002", "box003", "box004",
                                    "cylinder005", "sphere006")
add(T, TAB(RED, YEL, "top", "up"),
    "stack the red block on the yellow one",
    "move box001 onto box004")
add(T, [GRASP(BALL, "left")],
    "pick up the green ball with your left hand")
add(T, [GRASP(CYL)],
    "take hold of the blue cylinder")
add(T, TAB(CYL, YEL, "top", "up"),
    "place the blue cylinder on top of the flat box")
add(T, TAB(BALL, YEL, "top", "up"),
    "carefully put the ball on the yellow box")
add(T, TAB(GREEN, RED, "top", "up"),
    "pop the green box on top of the red box, cheers")
add(T, TAB(RED, BLUE, "top", "up", "left"),
    "with ur left hand put the red box on the blue box")
add(T, TAB(BALL, RED, "top", "up"),
    "first grab the ball, and after that set it on the red box")
add(T, TAB(BALL, RED, "top", "up", "left"),
    "put the ball onto the red box using your left hand")
add(T, TAB(BALL, CYL, "top", "up"),
    "pick up the ball and put it on the cylinder")
add(T, [REACH(GREEN, "top", "up")],
    "briefly touch the top of the green box")
add(T, [REACH(BALL, "body", "none", "left")],
    "touch the ball with your left hand")
add(T, [REACH(TT, "board", "up")],
    "touch the table")
add(T, [REACH(TT, "board", "up", "left", "right")],
    "put both hands on the table")
ambiguous(T,
          "pick up the box",
          "put the green one on the yellow box",
          "put the red box on the blue one",
          "touch the blue thing")
error(T,
      "sit down",
      "put the purple box on the table",
      "put the table on the red box")

if __name__ == "__main__":
    for line in LINES:
        print(json.dumps(line))
