"""Independent command set "people_a" for simhuman's offline planner.

Who: written by a helper session (author tag "people_a") started from the project session,
working only from /work/brief/corpus_brief.md and the UniHSI paper (ICLR 2024, Section 3 and
Appendix Tables 4-9).
How: every command was written from descriptions of what people ask virtual humans, assistants
and robots (animators blocking a scene, embodied-AI researchers scripting episodes, HRI users,
a curious user in a live web view), and the expected Chain of Contacts was written by hand from
the brief's conventions, BEFORE any run through the planner. The planner sources, the existing
corpus and its writer were not read, and simhuman was not run.
Date: 2026-11-26.

Run:  python3 write_people_a.py > people_a.jsonl
"""
import json

LINES = []


def add(scene, expect, *commands):
    """One plan case per command; expect = list of steps, each a list of pair strings."""
    for c in commands:
        LINES.append({"scene": scene, "command": c, "expect": expect})


def ambiguous(scene, *commands):
    for c in commands:
        LINES.append({"scene": scene, "command": c, "expect_ambiguous": True})


def error(scene, *commands):
    for c in commands:
        LINES.append({"scene": scene, "command": c, "expect_error": True})


# ----------------------------------------------------------------------------- helpers
def S(*items):
    """Build one step from pair strings and/or lists of pair strings."""
    step = []
    for it in items:
        if isinstance(it, str):
            step.append(it)
        else:
            step.extend(it)
    return step


def GC(o, side="front"):
    return f"{o}|none|none|none|{side}"


def SIT(o):
    return f"{o}|seat surface|pelvis|contact|up"


def SITBED(o):
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|not contact|up"]


def LIE(o):
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|contact|up"]


# seated extras (UniHSI Table 8), same step as SIT(o)
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


def CROSS(o):  # "cross your legs" = right foot on left knee
    return FOOT(o, "right", "left")


def LEANF(o):
    return [f"{o}|back surface|torso|not contact|none"]


def LEANB(o):
    return [f"{o}|back surface|torso|contact|none"]


# lying extras (UniHSI Table 9), same step as LIE(o)
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


# reaching while standing: own step
def REACH(o, part, d, *hands):
    hands = hands or ("right",)
    return [f"{o}|{part}|{h} hand|contact|{d}" for h in hands]


# reaching while seated (UniHSI Table 7): seat pair kept, hands 'none'
def SEATREACH(seat, o, part, *hands):
    hands = hands or ("left", "right")
    return [SIT(seat)] + [f"{o}|{part}|{h} hand|contact|none" for h in hands]


# tabletop pick and place
def TAB(a, b, part, d, hand="right"):
    grab = f"{a}|body|{hand} hand|contact|none"
    return [[grab], [grab, f"{b}|{part}|@{a}:body|contact|{d}"]]


# ============================================================================= sit_demo
# chair000 (brown) is NEAR, human stands 0.6 m in front of it with their back to it.
SD = "sit_demo"
C = "chair000"

# plain everyday phrasings and polite wrappers (assistant-style requests)
add(SD, [[SIT(C)]],
    "sit down",
    "Could you sit down on the chair, please?",
    "ok so just sit in the chair for me",
    "take a load off",                                   # idiom
    "I'd like you to sit on the seat behind you")        # part name used for the whole chair

# a pose that implies its base action (only one seat here, so it is answerable)
add(SD, [S(SIT(C), LEANB(C))], "sit back in the chair", "lean back")
add(SD, [S(SIT(C), CROSS(C))], "cross your legs")

# poses stated as a prepositional phrase / participle with the sit (UniHSI Table 8)
add(SD, [S(SIT(C), KNEE2(C))], "sit down with your hands on your knees")
add(SD, [S(SIT(C), STOM(C, "left", "right"))],
    "would you mind sitting on the chair with both hands on your belly")

# run-ons: extras added later become new steps, seat pair repeated (UniHSI Table 6 style)
add(SD, [[SIT(C)], S(SIT(C), KNEE2(C))], "sit down, then put your hands on your knees")
add(SD, [[SIT(C)], S(SIT(C), FOOT(C, "left", "right"))],
    "sit down and then put your left foot on your right knee")
add(SD, [[SIT(C)], [GC(C)]], "please sit down, then stand back up")
add(SD, [[SIT(C)], S(SIT(C), LEANB(C)), [GC(C)]], "sit, lean back for a sec, then get up")

# must not plan
error(SD, "stand up")                                     # already standing
error(SD, "lie down on the chair")                        # chair does not afford lying
error(SD, "sit down with your elbows on the armrests")    # this chair has no arms

# ============================================================================= living_room
# chair000 at table001 (desk height) with laptop002 on it; bed003 NEAR (human beside it,
# back to it); armchair004 red; sofa005 grey; stool006 brown. All but the bed are FAR.
LR = "living_room"
CH, TB, LP, BED, AC, SF, ST = ("chair000", "table001", "laptop002", "bed003",
                               "armchair004", "sofa005", "stool006")

# --- sofa: synonyms (couch), idioms, wrappers, casing
add(LR, [[GC(SF)], [SIT(SF)]],
    "sit on the sofa",
    "Can you go sit on the couch?",
    "grab a seat on the couch",                          # idiom
    "SIT ON THE COUCH",
    "plop down on the grey sofa",
    "sit on the couch!!")
add(LR, [[GC(SF)], S(SIT(SF), HANDARM2(SF))],
    "sit on the sofa with your hands on the armrests")
add(LR, [[GC(SF)], S(SIT(SF), HANDARM1(SF, "left"))],
    "would you mind sitting on the couch with your left hand on the armrest?")
add(LR, [[GC(SF)], S(SIT(SF), ELBOW1(SF, "right"))],
    "sit on the sofa, resting your right elbow on the arm of the sofa")
add(LR, [[GC(SF)], S(SIT(SF), HANDOFF(SF))],
    "sit on the couch with your hands off the armrests")
add(LR, [[GC(SF)], S(SIT(SF), LEANF(SF))], "lean forward on the sofa")       # implied sit

# --- armchair: pose implies base, colour as the name, several extras
add(LR, [[GC(AC)], S(SIT(AC), LEANB(AC))],
    "lean back in the armchair",
    "recline in the armchair")
add(LR, [[GC(AC)], [SIT(AC)]],
    "sit in the red chair",                              # armchair named by colour + hypernym
    "sit in the armchiar")                               # typo
add(LR, [[GC(AC)], S(SIT(AC), ELBOW2(AC))],
    "sit in the armchair with your elbows on the armrests")
add(LR, [[GC(AC)], S(SIT(AC), HANDARM1(AC, "right"))],
    "I'd like you to sit in the armchair with your right hand resting on the right armrest")
add(LR, [[GC(AC)], S(SIT(AC), CROSS(AC))],
    "sit in the armchair with one leg crossed over the other")
add(LR, [[GC(AC)], [SIT(AC)], S(SIT(AC), HANDARM2(AC))],
    "Go over to the armchair, sit down, then rest both hands on the armrests.")
add(LR, [[GC(AC)], [SIT(AC)], S(SIT(AC), LEANF(AC)), S(SIT(AC), LEANB(AC))],
    "sit in the armchair, then lean forward, then lean back again")

# --- chair at the table, laptop (UniHSI Table 4 / Table 7 desk work)
add(LR, [[GC(CH)], [SIT(CH)]], "sit at the table")
add(LR, [[GC(CH)], [SIT(CH)], SEATREACH(CH, LP, "keyboard")],
    "sit down at the desk, then type on the laptop")
add(LR, [[GC(CH)], SEATREACH(CH, LP, "keyboard")],
    "sit at the table with both hands on the laptop keyboard")

# --- stool
add(LR, [[GC(ST)], [SIT(ST)]], "sit on the stool")

# --- bed: NEAR, so no walk; idioms for lying
add(LR, [LIE(BED)],
    "lie down",                                          # only the bed affords lying
    "lie on the bed",
    "hop into bed",                                      # idiom
    "lay down on teh bed",                               # lay/lie + typo
    "lie down with your head on the pillow",             # prepositional pose = plain lie
    "now go ahead and get some sleep")                   # filler + idiom
add(LR, [SITBED(BED)],
    "sit on the bed",
    "sit on the edge of the bed")
add(LR, [S(LIE(BED), KNEEUP(BED, "left", "right"))], "lie on the bed with your knees up")
add(LR, [S(LIE(BED), SIDE(BED, "left"))], "lie on your left side on the bed")
add(LR, [S(LIE(BED), HPILLOW(BED, "left", "right"))], "lie down with both hands on the pillow")
add(LR, [S(LIE(BED), FOOTLIE(BED, "right", "left"))],
    "lie back on the bed with your right foot resting on your left knee")
add(LR, [HEADUP(BED)], "lie on the bed but keep your head up off the pillow")
add(LR, [SITBED(BED), LIE(BED)], "sit on the bed, then lie down")
add(LR, [LIE(BED), SITBED(BED), [GC(BED)]],
    "lie down, then sit up, and after that get out of bed")

# --- reaching while standing (part synonyms, default right hand, bare object -> default part)
add(LR, [REACH(BED, "pillow", "up")], "touch the pillow")
add(LR, [[GC(TB)], REACH(TB, "board", "up", "left", "right")],
    "walk to the table and put both hands flat on it")
add(LR, [[GC(LP)], REACH(LP, "keyboard", "up")], "touch the laptop")
add(LR, [[GC(AC)], REACH(AC, "right arm", "up")], "touch the armchair's right armrest")

# --- walking only
add(LR, [[GC(SF, "back")]], "go behind the sofa")
add(LR, [[GC(AC)]], "walk over to the armchair")
add(LR, [[GC(BED, "left")]], "go to the left side of the bed")

# --- multi-object run-ons (UniHSI Table 7 hard level)
add(LR, [[GC(SF)], [SIT(SF)], [GC(SF)], [GC(BED)], LIE(BED)],
    "sit on the couch for a bit, then go lie on the bed")
add(LR, [[GC(AC)], [SIT(AC)], S(SIT(AC), LEANB(AC)), [GC(AC)], [GC(BED)], LIE(BED)],
    "ok so first sit in the armchair, lean back, and after that go lie down on the bed")
add(LR, [LIE(BED), [GC(BED)], [GC(SF)], [SIT(SF)]],
    "lie on the bed, then get up and go sit on the sofa")
add(LR, [[GC(CH)], [SIT(CH)], SEATREACH(CH, LP, "keyboard"), [GC(CH)], [GC(BED)], LIE(BED)],
    "I want you to sit at the desk and type on the laptop for a while, and once you're done, go to bed")
add(LR, [SITBED(BED), [GC(BED)], [GC(AC)], [SIT(AC)]],
    "Sit on the bed first. Then go sit in the armchair.")

# --- must not plan
error(LR, "lie down on the couch")                  # lying only on a bed
error(LR, "sit on the table")                       # table does not afford sitting
error(LR, "sit on the laptop")
error(LR, "play the piano")                         # no piano in the scene
error(LR, "do a little dance")                      # unknown action
error(LR, "get up")                                 # already standing
error(LR, "")                                       # empty text

# --- ambiguous: several seats fit and nothing picks one
ambiguous(LR,
          "sit down",
          "put your hands on the armrests",              # sofa and armchair both have arms
          "lean back",                                   # chair, armchair, sofa have backs
          "sit with your hands on your knees",
          "go sit on the brown one",                     # chair000 or stool006
          "cross your legs")

# ============================================================================= office
# table000 with laptop001; chair002 pulled up at the table (NEAR); high_stool003 (black bar
# stool); box004 orange. All but the chair are FAR.
OF = "office"
T, L, OC, HS, BX = "table000", "laptop001", "chair002", "high_stool003", "box004"

# --- the desk chair is near: no walk
add(OF, [[SIT(OC)]],
    "sit down at the desk",                             # at the desk = in the chair at it
    "sit in the chair",
    "pull up a chair",                                  # idiom
    "Could you sit at the computer for me?")
add(OF, [SEATREACH(OC, L, "keyboard")], "sit at the desk with your hands on the keyboard")
add(OF, [[SIT(OC)], SEATREACH(OC, L, "keyboard")],
    "sit down, then type on the laptop",
    "go ahead and sit down at the desk and then start typing")
add(OF, [S(SIT(OC), LEANB(OC))], "lean back in the desk chair")                 # implied sit
add(OF, [S(SIT(OC), LEANF(OC))], "sit in the chair leaning forward")
add(OF, [S(SIT(OC), CROSS(OC))], "sit in the office chair with your legs crossed")
add(OF, [S(SIT(OC), STOM(OC, "left"))], "sit in the chair with your left hand on your stomach")
add(OF, [S(SIT(OC), KNEE1(OC, "right"))], "sit in the chair, right hand on your right knee")
add(OF, [[SIT(OC)], S(SIT(OC), LEANB(OC)), [GC(OC)]],
    "sit at the desk, then lean back, then stand up")

# --- bar stool: synonyms (bar stool, high stool, stool), colour
add(OF, [[GC(HS)], [SIT(HS)]],
    "sit on the bar stool",
    "hop up on the high stool",
    "sit on the stool",
    "can u sit on the black stool pls")
add(OF, [[GC(HS)], S(SIT(HS), KNEE2(HS))], "perch on the bar stool with your hands on your knees")
add(OF, [[GC(HS)], S(SIT(HS), FOOT(HS, "right", "left"))],
    "sit on the bar stool with your right foot on your left knee")

# --- box, table, laptop: walking and standing reaches
add(OF, [[GC(BX)]], "walk over to the box")
add(OF, [[GC(BX, "back")]], "go stand behind the box")
add(OF, [[GC(BX)], REACH(BX, "top", "up")], "touch the box", "Put your hand on the lid of the box.")
add(OF, [[GC(T, "left")]], "go to the left side of the desk")
add(OF, [[GC(T)], REACH(T, "board", "up")], "touch the desk")
add(OF, [[GC(L)], REACH(L, "screen", "front")], "go over to the laptop and touch the screen")
add(OF, [REACH(OC, "back surface", "front")], "touch the back of the chair")

# --- multi-object run-ons
add(OF, [[SIT(OC)], SEATREACH(OC, L, "keyboard"), [GC(OC)], [GC(HS)], [SIT(HS)]],
    "ok so sit at the desk, type for a bit, then get up and go sit on the bar stool")
add(OF, [[GC(HS)], [SIT(HS)], [GC(HS)], [GC(OC)], [SIT(OC)]],
    "sit on the bar stool, then come back and sit at the desk")
add(OF, [[GC(BX)], [GC(OC)], [SIT(OC)]],
    "walk to the box, and after that go sit down at the desk")

# --- must not plan
error(OF, "lie down")                               # no bed in the office
error(OF, "sit on the desk")
error(OF, "cook something")                         # unknown action
error(OF, "lean back on the bar stool")             # no backrest on a bar stool
error(OF, "turn on the TV")                         # no TV

# --- ambiguous
ambiguous(OF,
          "sit down",                               # chair002 or high_stool003
          "grab a seat real quick",
          "go to the brown thing")                  # table000 or chair002

# ============================================================================= bedroom
# bed000 white, stool001 brown, chair002 brown, box003 orange 0.5 m. Everything FAR.
BR = "bedroom"
B, BS, BC, BB = "bed000", "stool001", "chair002", "box003"

add(BR, [[GC(B)], LIE(B)],
    "lie down",
    "go to bed",                                    # idiom: sleep, not just walk
    "hit the hay",
    "Take a nap on the bed.")
add(BR, [[GC(B)], SITBED(B)], "sit on the bed")
add(BR, [[GC(B)], S(LIE(B), SIDE(B, "right"))], "lie down on your right side")
add(BR, [[GC(B)], S(LIE(B), KNEEUP(B, "left"))], "lie on the bed with your left knee up")
add(BR, [[GC(B)], S(LIE(B), HPILLOW(B, "right"))], "lie on the bed with your right hand on the pillow")
add(BR, [[GC(B, "right")]], "Go to the right side of the bed.")
add(BR, [[GC(BS)], [SIT(BS)]], "sit on the stool")
add(BR, [[GC(BC)], S(SIT(BC), LEANB(BC))], "lean back in the chair")
add(BR, [[GC(BB)], REACH(BB, "top", "up")], "touch the top of the box")
add(BR, [[GC(BS)], [SIT(BS)], [GC(BS)], [GC(B)], LIE(B)],
    "sit on the stool, then go lie down on the bed")
add(BR, [[GC(B)], SITBED(B), LIE(B), [GC(B)]],
    "sit on the bed, lie down, and then get up")

error(BR, "sit on the box")                         # box does not afford sitting
error(BR, "wave at me")                             # unknown action
error(BR, "jump on the bed")                        # unknown action

ambiguous(BR,
          "sit down",                               # bed, stool, chair
          "go to the brown one",                    # stool001 or chair002
          "have a seat with your legs crossed")     # stool or chair (or bed)

# ============================================================================= tabletop_demo
# Left to right: box001 red, box004 yellow (flat), box002 green (tall, thin), cylinder005 blue,
# box003 blue, sphere006 green. The human stands at table000.
TT = "tabletop_demo"
RED, GRN, BLU, YEL, CYL, SPH = "box001", "box002", "box003", "box004", "cylinder005", "sphere006"

add(TT, TAB(RED, BLU, "top", "up"), "put the red box on the blue box")
add(TT, TAB(YEL, RED, "top", "up"), "Could you place the yellow box on top of the red one?")
add(TT, TAB(SPH, YEL, "top", "up"), "put the ball on the yellow box")
add(TT, TAB(CYL, RED, "top", "up"), "set the blue cylinder on the red block")
add(TT, TAB(SPH, CYL, "top", "up"), "put the green sphere on top of the cylinder")
add(TT, TAB(RED, SPH, "body", "none"), "put the red box next to the ball")
add(TT, TAB(YEL, BLU, "body", "left"), "move the yellow box to the left of the blue box")
add(TT, TAB(SPH, RED, "body", "right"), "put the green ball to the right of the red box")
add(TT, TAB(BLU, GRN, "body", "back"), "place the blue box in front of the tall green box")
add(TT, TAB(RED, CYL, "body", "front"), "put the red box behind the cylinder")
add(TT, TAB(SPH, BLU, "top", "up", "left"), "grab the ball with your left hand and put it on the blue box")
add(TT, TAB(RED, BLU, "top", "up"), "put the leftmost box on top of the rightmost box")
add(TT, TAB(YEL, CYL, "body", "none"), "pick up the flat yellow box and set it down beside the cylinder")
add(TT, TAB(YEL, GRN, "top", "up"), "ok now put the yellow one on the green box, thanks")
add(TT, TAB(CYL, RED, "body", "none") + TAB(SPH, YEL, "top", "up"),
    "move the blue cylinder next to the red box, then put the ball on the yellow box")
add(TT, [REACH(SPH, "body", "none")], "touch the green ball")

error(TT, "put the red box on the plate")           # no plate
error(TT, "sit down")                               # nothing to sit on

ambiguous(TT,
          "put the red box on the blue one",        # box003 or cylinder005
          "put the box on the ball",                # four boxes
          "move the green thing next to the yellow box")  # box002 or sphere006

for l in LINES:
    print(json.dumps(l))
