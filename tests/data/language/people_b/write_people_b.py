"""Independent command set "people_b" for simhuman's offline planner.

Written by a helper session (corpus writer B) on 2026-11-26, from descriptions of
what people ask a virtual human to do and from the UniHSI paper (Section 3,
Tables 5-9), following /work/brief/corpus_brief.md.  Every expected plan was
written by hand from the brief's conventions BEFORE any run through the planner;
the planner sources, the existing corpus and the other writer's set were not read.

Imagined users: a game designer scripting NPCs, a physiotherapist describing
exercises at a chair or bed, a child typing casually, a non-native English
speaker, a roboticist writing terse commands, plus animators / HRI people /
curious web-view users.

Run:  python3 write_people_b.py > people_b.jsonl
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
# Every helper returns a LIST of pair strings, so a step is built by "+".
def GC(o, side="front"):
    return [f"{o}|none|none|none|{side}"]


def SIT(o):
    return [f"{o}|seat surface|pelvis|contact|up"]


def SITBED(o):
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|not contact|up"]


def LIE(o):
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|contact|up"]


# seated extras (same step as SIT)
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


# lying extras (same step as LIE)
def KNEEUP(o, *sides):
    return [f"{o}|mattress|{s} knee|not contact|none" for s in sides]


def HPILLOW(o, *sides):
    return [f"{o}|pillow|{s} hand|contact|none" for s in sides]


def SIDE(o, side):
    shoulder = "right" if side == "left" else "left"
    return [f"{o}|mattress|{shoulder} shoulder|not contact|none"]


def FOOTLIE(o, foot, knee):
    return [f"{o}|{knee} knee|{foot} foot|contact|up"]


def HEADUP(o):
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|not contact|none"]


# reaching
def REACH(o, part, d, *hands):
    hands = hands or ("right",)
    return [f"{o}|{part}|{h} hand|contact|{d}" for h in hands]


def SEATREACH(o, part, *hands):
    """Seated reach (UniHSI Table 7): hands carry direction none."""
    hands = hands or ("left", "right")
    return [f"{o}|{part}|{h} hand|contact|none" for h in hands]


def TAB(a, b, part, d, hand="right"):
    grasp = [f"{a}|body|{hand} hand|contact|none"]
    return [grasp, grasp + [f"{b}|{part}|@{a}:body|contact|{d}"]]


def GRASP(a, hand="right"):
    return [f"{a}|body|{hand} hand|contact|none"]


# =================================================================== sit_demo
S = "sit_demo"
c = "chair000"

# plain request, and a child's typo version
add(S, [SIT(c)], "sit down")
add(S, [SIT(c)], "sit on teh chair pls")
# roboticist: terse, one instruction per sentence -> the extra is a later step
add(S, [SIT(c), SIT(c) + LEANB(c)], "sit. lean back.")
# physiotherapist: seated posture given with the sit -> one step
add(S, [SIT(c) + KNEE2(c)], "Sit in the chair with both hands resting on your knees.")
add(S, [SIT(c) + KNEE1(c, "left")], "Sit with your left hand on your left knee, please.")
# game designer scripting an NPC, third person, comma run-on
add(S, [SIT(c), SIT(c) + FOOT(c, "right", "left"), GC(c)],
    "NPC sits on the chair, crosses its legs, then stands up")
# idiom wrapper + a later extra joined by "and"
# (after the first run) a pose after a bare "and" joins the sit step (main corpus, set A)
add(S, [SIT(c) + LEANF(c)], "take a seat and lean forward a little")
# non-native speaker, article dropped
add(S, [SIT(c) + STOM(c, "right")], "Please sit on chair with the right hand on the stomach.")
# politeness wrapper, sit then get up
add(S, [SIT(c), GC(c)], "Would you mind sitting down for a sec and then getting back up?")
# three-step run-on, one extra per later step (seat pair repeated, extras not accumulated)
add(S, [SIT(c), SIT(c) + LEANB(c), SIT(c) + STOM(c, "left", "right")],
    "sit down, lean back, and then rest both hands on your belly")
# pose implying its base action (chair is near: no walk)
add(S, [SIT(c) + LEANB(c)], "Lean back in the chair.")
# standing reaches at a near object
add(S, [REACH(c, "seat surface", "up", "left")], "touch the seat of the chair with your left hand")
add(S, [REACH(c, "back surface", "front")], "put your hand on the backrest")
# walking only, to a side
add(S, [GC(c, "back")], "go stand behind the chair")
# errors: already standing; nothing here affords lying
error(S, "stand up")
error(S, "lie down for a bit")

# =================================================================== living_room
L = "living_room"
ch, tb, lp, bed, arm, sofa, st = ("chair000", "table001", "laptop002", "bed003",
                                  "armchair004", "sofa005", "stool006")

# --- bed (NEAR): idioms, prepositional poses, physio exercises
add(L, [LIE(bed)], "lie down")                       # only the bed affords lying
add(L, [LIE(bed)], "hop into bed")
add(L, [LIE(bed)], "Lie down with your head on the pillow.")
add(L, [SITBED(bed)], "sit on the edge of the bed")
add(L, [LIE(bed) + KNEEUP(bed, "left", "right")], "lay on the bed with ur knees up")  # child
add(L, [LIE(bed) + KNEEUP(bed, "left")],
    "Lying on the bed, bend your left knee up so the foot stays flat.")           # physio
add(L, [LIE(bed) + SIDE(bed, "right")], "Now lie on your right side on the bed.")  # physio
add(L, [LIE(bed), HEADUP(bed)], "lie on the bed and then lift your head off the pillow")
add(L, [HEADUP(bed)], "lie in bed with your head raised off the pillow")
add(L, [LIE(bed), LIE(bed) + FOOTLIE(bed, "right", "left")],
    "lie down, then cross your legs")
add(L, [LIE(bed) + SIDE(bed, "left") + HPILLOW(bed, "left")],
    "lie on your left side on the bed with your left hand on the pillow")
add(L, [SITBED(bed), LIE(bed) + HPILLOW(bed, "left", "right")],
    "I'd like you to sit on the bed first, then lie back with both hands on the pillow.")
# standing reaches at the near bed
add(L, [REACH(bed, "pillow", "up")], "touch the pillow")
add(L, [REACH(bed, "mattress", "up", "left", "right")], "put both hands on the mattress")

# --- walking only
add(L, [GC(sofa)], "head over to the couch")
add(L, [GC(bed, "left")], "go to the left side of the bed")

# --- seats far away: walk first
add(L, [GC(sofa), SIT(sofa)], "take a load off on the couch")
add(L, [GC(st), SIT(st)], "go sit on the stool")
add(L, [GC(arm), SIT(arm) + LEANB(arm)], "lean back in the armchair")           # implied sit
add(L, [GC(arm), SIT(arm) + ELBOW2(arm)],
    "Could you sit in the armchair with both elbows on the armrests?")
add(L, [GC(arm), SIT(arm) + HANDARM1(arm, "right")],
    "sit in the red chair with your right hand on the armrest")   # colour picks the armchair
add(L, [GC(sofa), SIT(sofa) + ELBOW1(sofa, "left")],
    "would you mind sitting on the sofa with your left elbow on the armrest")
add(L, [GC(sofa), SIT(sofa) + FOOT(sofa, "right", "left")], "SIT ON THE SOFA WITH YOUR LEGS CROSSED")
add(L, [GC(st), SIT(st) + STOM(st, "left", "right")],
    "sit on the stool with both hands on your stomach")
add(L, [GC(sofa), SIT(sofa), SIT(sofa) + KNEE2(sofa)],
    "Please go to sofa and sit down on it, and put the hands on the knees.")   # non-native
add(L, [GC(arm), SIT(arm) + HANDARM2(arm), SIT(arm) + HANDOFF(arm)],
    "sit in the armchair with your hands on the armrests, then lift them off")
add(L, [GC(arm), SIT(arm), SIT(arm) + HANDARM2(arm), GC(arm)],
    "NPC walks to the armchair, sits, rests its hands on both armrests, then gets up")

# --- desk / laptop
add(L, [GC(ch), SIT(ch), SIT(ch) + SEATREACH(lp, "keyboard")],
    "sit at the desk and type on the laptop")
add(L, [GC(lp), REACH(lp, "keyboard", "up")], "go put your hand on the laptop")

# --- multi-object run-ons
add(L, [GC(sofa), SIT(sofa), GC(sofa), GC(bed), LIE(bed)],
    "ok so first chill on the sofa for a bit, after that go lie down in bed")
add(L, [LIE(bed), GC(bed), GC(ch), SIT(ch)],
    "get into bed, then get up and sit at the desk")

# --- ambiguous: several seats / armrests / brown objects fit
ambiguous(L, "sit down")
ambiguous(L, "grab a seat")
ambiguous(L, "put your hands on the armrests")
ambiguous(L, "lean back and relax")
ambiguous(L, "walk over to the brown one")

# --- errors: affordance, missing object, unknown action
error(L, "lie down on the couch")          # lying only on a bed
error(L, "lean back on the stool")         # the stool has no backrest
error(L, "go play the piano")
error(L, "do a little dance for me")

# =================================================================== office
O = "office"
t, lap, oc, hs, bx = "table000", "laptop001", "chair002", "high_stool003", "box004"

# --- the chair at the desk is NEAR
add(O, [SIT(oc)], "go ahead and grab a seat at the computer")
add(O, [SIT(oc) + LEANB(oc)], "lean back in the office chair")
# (after the first run) a pose after a bare "and" joins the sit step
add(O, [SIT(oc) + LEANF(oc)], "sit in the chair and lean forward toward the screen")
add(O, [SIT(oc) + SEATREACH(lap, "keyboard")], "Sit with your hands on the keyboard.")
add(O, [SIT(oc), SIT(oc) + SEATREACH(lap, "keyboard")],
    "sit at the desk, then start typing on the laptop")
add(O, [SIT(oc), SIT(oc) + SEATREACH(lap, "keyboard")], "sit chair002 -> type on laptop001")  # roboticist
add(O, [SIT(oc) + KNEE1(oc, "right")],
    "Seated in the chair, place your right hand on your right knee.")           # physio
add(O, [SIT(oc) + LEANF(oc) + KNEE2(oc)],
    "Sit on the chair without touching the backrest, hands on your knees.")      # physio
add(O, [SIT(oc), GC(oc)],
    "real quick, sit in the chair and then stand back up")

# --- the bar stool (FAR)
add(O, [GC(hs), SIT(hs)], "sit on the bar stool")
add(O, [GC(hs), SIT(hs)], "perch on the tall stool")
add(O, [GC(hs), SIT(hs)], "goto high_stool003; sit")                            # roboticist
add(O, [GC(hs), SIT(hs) + KNEE2(hs)], "sit on the bar stool with your hands on your knees")
add(O, [GC(hs), SIT(hs) + FOOT(hs, "left", "right")],
    "sit on the stool with your left foot resting on your right knee")

# --- box, desk, laptop reaches (all FAR)
add(O, [GC(bx)], "walk over to the orange box")
add(O, [GC(bx), REACH(bx, "top", "up")], "go to the box and put your hand on top of it")
add(O, [GC(bx), REACH(bx, "top", "up", "left", "right")], "place both hands on the lid of the box")
add(O, [GC(bx), REACH(bx, "top", "up")], "Could you touch the box for me?")
add(O, [GC(t, "back")], "go behind the desk")
add(O, [GC(t), REACH(t, "board", "up", "left", "right")], "put both palms flat on the desk")
add(O, [GC(lap), REACH(lap, "screen", "front")], "touch the laptop screen")
add(O, [GC(lap), REACH(lap, "keyboard", "up", "left")],
    "press a key on the laptop with your left hand")

# --- multi-object run-ons
# (after the first run) "move over to X" is a walk; no sit on X is said (brief: walking only)
add(O, [SIT(oc), GC(oc), GC(hs)],
    "sit at the desk for a while, then move over to the bar stool")
add(O, [GC(hs), SIT(hs), GC(hs), GC(bx), REACH(bx, "top", "up")],
    "sit on the high stool, once you're done walk over and touch the box")
add(O, [GC(bx), REACH(bx, "top", "up"), GC(oc), SIT(oc)],
    "Walk to the box, touch it, then come back and sit in the chair.")

# --- ambiguous
ambiguous(O, "have a seat")
ambiguous(O, "go to the brown one")

# --- errors
error(O, "sit on the desk")
error(O, "sit on the laptop")
error(O, "open the fridge and grab a soda")

# =================================================================== bedroom
B = "bedroom"
bd, bst, bch, bbx = "bed000", "stool001", "chair002", "box003"

add(B, [GC(bd), LIE(bd)], "go to bed")                  # idiom
add(B, [GC(bd), SITBED(bd)], "sit on the bed")
add(B, [GC(bd), LIE(bd) + KNEEUP(bd, "left", "right")], "lie on the bed with both knees bent up")
add(B, [GC(bd), LIE(bd) + SIDE(bd, "left")], "I want that you lie in the bed on the left side")  # non-native
add(B, [GC(bd), LIE(bd), GC(bd)], "lie in bed, then get up")
add(B, [GC(bd), SITBED(bd), LIE(bd), GC(bd)], "sit on the bed then lay down then get up")     # child
add(B, [GC(bst), SIT(bst)], "Sit on the stool.")
# (after the first run) a pose after a bare "and" joins the sit step
add(B, [GC(bch), SIT(bch) + LEANB(bch)], "sit on the chair and lean back")
add(B, [GC(bbx), REACH(bbx, "top", "up")], "touch the orange box")
add(B, [GC(bst), SIT(bst), GC(bst), GC(bd), LIE(bd)], "sit on the stool, then go lie on the bed")
ambiguous(B, "sit down please")
error(B, "")
error(B, "sit on the box")               # a box is not a seat in this system

# =================================================================== tabletop_demo
T = "tabletop_demo"
red, green, blue, yellow, cyl, ball = ("box001", "box002", "box003", "box004",
                                       "cylinder005", "sphere006")

add(T, [GRASP(red)], "pick up the red box")
add(T, [REACH(ball, "body", "none")], "touch the ball")
add(T, TAB(red, blue, "top", "up"), "put the red box on the blue box")
add(T, TAB(ball, yellow, "top", "up"), "place the ball on top of the yellow box")
add(T, TAB(yellow, red, "top", "up"), "stack the yellow box onto the red one")
add(T, TAB(cyl, green, "body", "none"), "put the cylinder next to the green box")
add(T, TAB(yellow, cyl, "body", "left"), "move the yellow box to the left of the blue cylinder")
add(T, TAB(ball, red, "body", "front"), "set the green ball behind the red box")
add(T, TAB(blue, green, "body", "back"), "Put the blue box in front of the tall green box.")
add(T, TAB(red, cyl, "top", "up", "left"), "with your left hand, put the red box on the cylinder")
add(T, TAB(green, ball, "body", "right"), "pick box002, place right of sphere006")   # roboticist
add(T, TAB(ball, cyl, "top", "up") + TAB(red, yellow, "top", "up"),
    "put the ball on the cylinder, and after that the red box on the flat yellow one")
ambiguous(T, "pick up the green one")
ambiguous(T, "put the blue thing on the red box")
error(T, "put the purple box on the red box")
error(T, "sit on the table")

for l in LINES:
    print(json.dumps(l))
