"""Independent command set "people_d" for simhuman's offline planner (held out).

Written by a helper session (corpus writer D) on 2026-11-28.  Sources: the UniHSI paper
(ICLR 2024, Section 3 and Tables 5-9), docs/FORMATS.md (plan format, built-in scenes
table, get-close stand points, the "Language commands" conventions), the helper functions
of people_b/write_people_b.py (lines 1-141: the pair conventions, re-implemented below
with the same pairs), the helper section of people_c/write_people_c.py (lines 1-60) and
the "Conventions applied" section of people_c/README.md.  Every expectation below was
written by hand from those conventions BEFORE anything was run; the planner sources, the
main corpus and the commands of sets A, B and C were not read, and no planner binary was
built or run.

Imagined users (new, not those of A, B and C): an animator writing shot notes, an
embodied-AI researcher writing benchmark task strings, a parent talking to a young child,
a yoga / fitness instructor, a smart-home user talking through a voice assistant's wake
word ("Alexa, tell the avatar to ..."), a person typing on a phone (typos and autocorrect
slips), a sports commentator, American and Australian casual speakers, someone writing
formal, legalistic instructions, someone who writes long multi-sentence paragraphs with
context, someone using abbreviations (and one emoji), someone phrasing the command as a
wish or question, and someone correcting themselves mid-sentence.

Run:  python3 write_people_d.py > people_d.jsonl
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
    """Sit on the edge of a bed (UniHSI Table 5)."""
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|not contact|up"]


def LIE(o):
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|contact|up"]


# seated extras (same step as the seat pairs), UniHSI Table 8
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
    """Seated: <foot> foot on <knee> knee."""
    return [f"{o}|{knee} knee|{foot} foot|contact|none"]


def LEANF(o):
    return [f"{o}|back surface|torso|not contact|none"]


def LEANB(o):
    return [f"{o}|back surface|torso|contact|none"]


# lying extras (same step as LIE), UniHSI Table 9
def KNEEUP(o, *sides):
    return [f"{o}|mattress|{s} knee|not contact|none" for s in sides]


def HPILLOW(o, *sides):
    return [f"{o}|pillow|{s} hand|contact|none" for s in sides]


def SIDE(o, side):
    """Lying on the <side> side lifts the other shoulder."""
    shoulder = "right" if side == "left" else "left"
    return [f"{o}|mattress|{shoulder} shoulder|not contact|none"]


def FOOTLIE(o, foot, knee):
    return [f"{o}|{knee} knee|{foot} foot|contact|up"]


def HEADUP(o):
    """Lying with the head raised: replaces the head pair of LIE."""
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|not contact|none"]


# reaching
def REACH(o, part, d, *hands):
    """Standing reach: up for tops/seats/boards, front for screens/backs, none for bodies."""
    hands = hands or ("right",)
    return [f"{o}|{part}|{h} hand|contact|{d}" for h in hands]


def SEATREACH(o, part, *hands):
    """Seated reach (UniHSI Table 7): hands carry direction none."""
    hands = hands or ("left", "right")
    return [f"{o}|{part}|{h} hand|contact|none" for h in hands]


def TAB(a, b, part="top", d="up", hand="right"):
    """Pick a and put it on b: grasp step, then grasp + object-object pair."""
    grasp = [f"{a}|body|{hand} hand|contact|none"]
    return [grasp, grasp + [f"{b}|{part}|@{a}:body|contact|{d}"]]


def GRASP(a, hand="right"):
    return [f"{a}|body|{hand} hand|contact|none"]


# ================================================================ sit_demo
# chair000 at (0, 0), yaw 0, no arms.  Human at (0.625, 0), 0.4 m in front of the seat's
# front edge, facing away: no get-close step before sitting.
S = "sit_demo"
C0 = "chair000"

# animator, shot notes
add(S, [SIT(C0), SIT(C0) + LEANB(C0)],
    "char sits on chair, settles back against the backrest")
# embodied-AI researcher, task strings
add(S, [SIT(C0), GC(C0)],
    "Task 017: sit on chair000, then stand up.")
add(S, [SIT(C0) + STOM(C0, "left", "right"), GC(C0)],
    "Task 018: sit on chair000; hands on stomach; stand up.")
# parent to a child
add(S, [SIT(C0) + KNEE2(C0)],
    "Sweetie, can you sit on the chair and put your hands on your knees? Good job.")
# yoga instructor
add(S, [SIT(C0), SIT(C0) + KNEE1(C0, "right")],
    "Come to sit on the chair. Rest your right hand on your right knee.")
add(S, [SIT(C0), SIT(C0) + LEANF(C0)],
    "Sit tall on the chair, then lean forward, away from the backrest.")
# smart-home user
add(S, [SIT(C0)],
    "Alexa, tell the avatar to sit on the chair")
# phone typist
add(S, [SIT(C0) + FOOT(C0, "right", "left")],
    "sit in hte chsir and cross ur right foot over ur left knee")
# sports commentator
add(S, [SIT(C0), SIT(C0) + LEANB(C0)],
    "And he sits down in the chair... and now he's leaning right back!")
# American casual
add(S, [SIT(C0), GC(C0)],
    "alright, sit yourself down, then get back up")
# Australian casual
add(S, [SIT(C0)],
    "righto mate, plonk yourself down on the chair")
# formal / legalistic
add(S, [SIT(C0) + STOM(C0, "left", "right")],
    "The subject shall be seated upon the chair with both hands placed upon the abdomen.")
# long paragraph
add(S, [SIT(C0), SIT(C0) + LEANF(C0), GC(C0)],
    "I want him to sit on the chair first. Once he is sitting, he should lean forward a "
    "little, like he is listening closely. After that he can stand up again.")
# abbreviations and an emoji
add(S, [SIT(C0) + KNEE2(C0)],
    "sit on chair w/ hands on knees pls \U0001F64F")
# wish / question
add(S, [SIT(C0) + FOOT(C0, "left", "right")],
    "Would it be possible for him to sit on the chair and cross his left foot over his "
    "right knee?")
# correction mid-sentence
add(S, [SIT(C0) + KNEE1(C0, "right")],
    "Sit on the chair with your left hand on your left knee -- no, your right hand on "
    "your right knee.")

error(S,
      # the chair of sit_demo has no arms
      "Sit on the chair and rest your elbows on the armrests.",
      "do ten jumping jacks next to the chair",
      # no sofa in sit_demo
      "Go lie on the sofa")

# ================================================================ living_room
# chair000 (0.95, 0) 0; table001 (2.2, 0) 180; laptop002 on the table; bed003 (4.2, -2.5) 90;
# armchair004 (0, 2.5) -90; sofa005 (-2.5, 0) 0; stool006 (-0.5, -2.5).
# Human at (4.0, -1.35): the bed is 0.4 m away (no get-close); every other object > 1 m.
# The table's front stand point is (1.375, 0): chair000's seat is 0.2 m from it.
L = "living_room"
LC, LT, LL, LB, LA, LS, LST = ("chair000", "table001", "laptop002", "bed003",
                               "armchair004", "sofa005", "stool006")

# animator
add(L, [GC(LA), SIT(LA) + HANDARM2(LA)],
    "SHOT 7 - char crosses to the armchair, sits, both hands on the armrests.")
add(L, [GC(LS), SIT(LS), SIT(LS) + LEANB(LS)],
    "char walks over to the sofa and drops onto it, then leans back into the cushions")
# researcher
add(L, [LIE(LB) + KNEEUP(LB, "left", "right")],
    "Goal: lie on bed003 with knees raised.")
add(L, [GC(LST), SIT(LST), GC(LST), GC(LS), SIT(LS)],
    "Instruction: sit on stool006, stand up, walk to sofa005, sit on sofa005.")
add(L, [GC(LC), SIT(LC) + SEATREACH(LL, "keyboard", "left", "right")],
    "Task: sit on chair000 with both hands on laptop002's keyboard.")
# parent
add(L, [GC(LS), SIT(LS) + STOM(LS, "left", "right")],
    "Okay buddy, go sit on the big sofa and put your hands on your tummy")
add(L, [LIE(LB)],
    "Bedtime, kiddo. Lie down on the bed with your head on the pillow.")
# yoga instructor
add(L, [SITBED(LB), SITBED(LB) + KNEE2(LB)],
    "Find a seat on the edge of the bed. Place both hands on your knees and breathe.")
add(L, [LIE(LB), LIE(LB) + FOOTLIE(LB, "right", "left")],
    "Lie back on the bed, bring your right foot to rest on your left knee.")
add(L, [LIE(LB) + SIDE(LB, "left")],
    "Lie down on the bed and roll over onto your left side.")
# smart-home user
add(L, [GC(LA), SIT(LA) + ELBOW2(LA)],
    "Hey Google, make the avatar sit in the armchair and rest its elbows on the armrests")
add(L, [LIE(LB) + HPILLOW(LB, "left", "right")],
    "Siri, have the person lie on the bed with both hands on the pillow")
# phone typist
add(L, [GC(LT)],
    "wlak to the tabel")
add(L, [GC(LS), SIT(LS) + LEANB(LS)],
    "sit on the sofa annd lean bakc")
add(L, [GC(LA), SIT(LA) + ELBOW1(LA, "right")],
    "Sit on the arm chair and put your right elbow on the right armrest")
# sports commentator
add(L, [GC(LS), SIT(LS), SIT(LS) + LEANF(LS)],
    "And he makes his way over to the couch and sits himself down. Now he leans right "
    "forward!")
# American casual
add(L, [GC(LS), SIT(LS)],
    "head on over and park it on the couch")
add(L, [GC(LT), REACH(LT, "board", "up", "right"), SIT(LC)],
    "walk over to the table, touch it, then sit in the chair")
add(L, [SITBED(LB), GC(LB), GC(LS)],
    "sit on the bed a minute, then get up and head over to the couch")
# Australian casual
add(L, [GC(LST), SIT(LST), GC(LST), GC(LB), LIE(LB)],
    "reckon you could sit on the stool, mate? then lie down on the bed")
# formal / legalistic
add(L, [GC(LL), REACH(LL, "screen", "front", "right")],
    "Kindly proceed to the laptop and touch its screen with the right hand.")
add(L, [GC(LA), SIT(LA) + HANDOFF(LA)],
    "The person shall sit in the armchair with the hands held clear of the armrests.")
# long paragraph
add(L, [GC(LC), SIT(LC), SIT(LC) + LEANB(LC), GC(LC), GC(LB),
        LIE(LB) + KNEEUP(LB, "left", "right")],
    "So here's what I'd like. First he goes over to the chair by the table and sits down. "
    "He should lean back against the backrest while he sits there. Then he stands up, "
    "walks over to the bed and lies down on it with his knees up.")
# abbreviations
add(L, [GC(LA), SIT(LA) + HANDARM1(LA, "left")],
    "plz walk 2 the armchair & sit w/ L hand on L armrest thx")
# wish / question
add(L, [LIE(LB) + SIDE(LB, "right")],
    "Could we maybe have her lying on the bed, on her right side?")
add(L, [GC(LS), SIT(LS) + ELBOW1(LS, "left")],
    "I'd love to see him sitting on the sofa with his left elbow propped on the armrest.")
# corrections
add(L, [GC(LST), SIT(LST)],
    "go to the chair, actually no, the stool, and sit on it")
add(L, [GC(LS), SIT(LS) + FOOT(LS, "left", "right")],
    "sit on the sofa with your right foot on your left knee, sorry, left foot on right knee")

ambiguous(L,
          # chair, armchair, sofa, stool and bed are all seats
          "Okay Google, make him sit down.",
          # chair, armchair and sofa have backrests
          "Now gently lean back.",
          # armchair and sofa have armrests
          "Rest your elbows on the armrests please.",
          # chair, armchair, sofa, stool all have a seat
          "could you touch the seat?")

error(L,
      "Alexa, turn the TV on",
      "sit on the piano bench mate",
      # a table is not something to lie on
      "The person shall lie down upon the table.")

# ================================================================ office
# table000 (1.8, 0) 180; laptop001 (1.565, 0, 0.75) 180; chair002 (0.8, 0) 0;
# high_stool003 (1.0, 1.8); box004 (2.0, -1.6).  Human at (0, -1): chair002 is 0.94 m
# away (no get-close); every other object > 1 m.  The laptop is 0.42 m from the seat.
O = "office"
OT, OL, OC, OH, OB = "table000", "laptop001", "chair002", "high_stool003", "box004"

# animator
add(O, [SIT(OC), SIT(OC) + LEANF(OC)],
    "Beat 3: he sits in the desk chair, then leans forward.")
# researcher
add(O, [SIT(OC) + SEATREACH(OL, "keyboard", "left", "right")],
    "Task: sit on chair002 with both hands on the keyboard of laptop001.")
add(O, [GC(OB), REACH(OB, "top", "up", "left")],
    "Task: walk to box004, touch its top with the left hand.")
add(O, [GC(OH), SIT(OH), GC(OH), GC(OT)],
    "Task: sit on high_stool003, then stand up and walk to table000.")
# parent
add(O, [GC(OH), SIT(OH)],
    "Honey, go sit on the tall stool, okay?")
# yoga instructor
add(O, [SIT(OC) + KNEE2(OC)],
    "Sit on the office chair and let your hands rest on your knees.")
# phone typist
add(O, [SIT(OC), SIT(OC) + SEATREACH(OL, "keyboard", "left")],
    "sit on hte chair, put ur left hand on hte laptop keybaord")
add(O, [GC(OH), SIT(OH), GC(OH)],
    "Sit on the high stoop then stand up")
add(O, [SIT(OC), SIT(OC) + SEATREACH(OL, "screen", "right")],
    "Sit on the chair, then touch the laptop\u2019s screen with ur right hand")
# sports commentator
add(O, [GC(OB), REACH(OB, "top", "up", "left", "right")],
    "He goes to the box, reaches out and touches it with both hands!")
# American casual
add(O, [SIT(OC) + LEANB(OC)],
    "alright so sit down in the chair and lean way back")
# formal
add(O, [GC(OH), SIT(OH), GC(OH), GC(OB)],
    "The operator requests that the figure be seated upon the high stool and thereafter "
    "proceed to the storage box.")
# long paragraph (box front stand point (2.65, -1.6) is > 1 m from chair002)
add(O, [GC(OB), REACH(OB, "top", "up", "right"), GC(OC),
        SIT(OC) + SEATREACH(OL, "keyboard", "left", "right")],
    "He's been working all day. He walks over to the box in the corner and puts his "
    "right hand on top of it. Then he turns and sits down in the chair at the desk with "
    "both hands on the keyboard.")
# wish / question
add(O, [SIT(OC) + STOM(OC, "right")],
    "Is it possible to have her sit on the desk chair with her right hand on her stomach?")
# correction
add(O, [GC(OH)],
    "walk to the box -- no, to the bar stool")
# abbreviations
add(O, [SIT(OC) + KNEE1(OC, "left")],
    "sit in desk chair w/ L hand on L knee")

ambiguous(O,
          # chair002 and high_stool003
          "Take a seat.",
          # table000's board ("top") and box004's top
          "Walk over and touch the top, please.")

error(O,
      # no bed in the office
      "lie down on the bed",
      "water the plant by the window",
      # no armchair in the office
      "sit in the armchair")

# ================================================================ bedroom
# bed000 (2.5, 0) 180: front (long side) faces world -x, at x = 1.75; pillow at world -y.
# stool001 (2.9, 1.5); chair002 (0, 2.2) -90; box003 (-1.2, -1.5).  Human at (0, 0):
# every object > 1 m away.
B = "bedroom"
BB, BS, BC, BX = "bed000", "stool001", "chair002", "box003"

# animator
add(B, [GC(BB), SITBED(BB), LIE(BB)],
    "Shot 9: char goes to the bed, sits on the edge, then lies back onto the pillow.")
add(B, [GC(BB), LIE(BB) + KNEEUP(BB, "left", "right")],
    "Shot 10: lying on the bed, char pulls both knees up.")
# researcher
add(B, [GC(BB), LIE(BB) + HPILLOW(BB, "left")],
    "Task: approach bed000 and lie down on it with the left hand on the pillow.")
add(B, [GC(BS), SIT(BS), GC(BS), GC(BX), REACH(BX, "top", "up", "right")],
    "Task: sit on stool001, then walk to box003 and touch it with the right hand.")
# parent
add(B, [GC(BS), SIT(BS), GC(BS), GC(BC), SIT(BC)],
    "Can you sit on the little stool for me, then come over and sit on the chair?")
# yoga instructor
add(B, [GC(BC), SIT(BC), SIT(BC) + FOOT(BC, "left", "right")],
    "Come and sit on the chair. Cross your left ankle over your right knee.")
# smart-home user
add(B, [GC(BB), LIE(BB) + SIDE(BB, "right") + HPILLOW(BB, "right")],
    "Alexa, ask the avatar to lie in bed on its right side with its right hand on the pillow.")
# phone typist
add(B, [GC(BC), SIT(BC)],
    "go too the chair and sti down")
add(B, [GC(BB), HEADUP(BB)],
    "lay on the bed w ur head up")
# sports commentator
add(B, [GC(BC), SIT(BC), SIT(BC) + FOOT(BC, "right", "left")],
    "He heads for the chair and sits down. Now he's crossing his right foot over his left "
    "knee!")
# American casual
add(B, [GC(BX), REACH(BX, "top", "up", "right"), GC(BB), LIE(BB)],
    "swing by the box and tap it, then go lie down on the bed")
# formal
add(B, [GC(BB), LIE(BB) + KNEEUP(BB, "right")],
    "It is requested that the person recline upon the bed, with the head resting on the "
    "pillow and the right knee raised.")
# long paragraph
add(B, [GC(BX), REACH(BX, "top", "up", "left"), GC(BB), SITBED(BB),
        LIE(BB) + HPILLOW(BB, "left", "right")],
    "Okay so in this one he walks over to the box and touches the top of it with his left "
    "hand. After that he goes over to the bed and sits on it for a while. Finally he lies "
    "down with both hands on the pillow.")
# wish / question
add(B, [GC(BC), SIT(BC) + KNEE2(BC)],
    "Could he perhaps sit in the chair with his hands on his knees?")
# correction
add(B, [GC(BB), LIE(BB) + HPILLOW(BB, "right")],
    "lie on the bed with your left -- no, right -- hand on the pillow")
# Australian casual
add(B, [GC(BB), SITBED(BB), GC(BB), GC(BS)],
    "Mate, go sit on the bed, then get up and walk over to the stool.")

ambiguous(B,
          # bed000, stool001, chair002
          "Sit down please.",
          # chair002's and stool001's seat cushion, bed000's pillow
          "Put your hand on the cushion.",
          # stool001 and chair002
          "Put your hand on the seat.")

error(B,
      # no sofa in the bedroom
      "lie down on the couch",
      "open the wardrobe",
      "make the bed")

# ================================================================ tabletop_demo
# table000 (1.0, 0) 180; box001 red (0.85, 0.3); box002 green (0.85, 0); box003 blue
# (0.85, -0.3); box004 yellow, flat (1.1, 0.15); cylinder005 blue (1.1, -0.15); sphere006
# green (1.1, -0.4).  Human at (0.2, 0): everything within 1 m (no get-close steps).
T = "tabletop_demo"
TT = "table000"
RED, GREEN, BLUE, YEL, CYL, BALL = ("box001", "box002", "box003", "box004",
                                    "cylinder005", "sphere006")

# animator
add(T, TAB(RED, YEL),
    "Shot 1: char picks up the red block and sets it on the yellow box.")
# researcher
add(T, TAB(BALL, CYL, hand="left"),
    "Task: place sphere006 on top of cylinder005 using the left hand.")
# parent
add(T, TAB(BALL, YEL),
    "Can you put the green ball on the yellow box, sweetie?")
add(T, [REACH(BALL, "body", "none", "left")],
    "Gently touch the green ball with your left hand, sweetie.")
add(T, [REACH(TT, "board", "up", "right")],
    "Put your hand flat on the table, honey.")
# smart-home user
add(T, TAB(CYL, YEL),
    "Alexa, tell him to put the blue cylinder on the yellow box")
# phone typist
add(T, TAB(RED, CYL),
    "put hte red box on the bleu cylinder")
add(T, TAB(GREEN, YEL),
    "Pick up the green box and put it on the yellow boy")
# sports commentator
add(T, TAB(BLUE, RED),
    "He grabs the blue box... and stacks it on the red one!")
# American casual
add(T, TAB(BALL, CYL),
    "grab the ball and stick it on top of the blue cylinder")
# formal
add(T, [GRASP(YEL)],
    "The agent shall grasp the yellow box with the right hand.")
# long paragraph
add(T, TAB(CYL, GREEN) + TAB(RED, YEL),
    "There are a bunch of blocks on the table. I want him to take the blue cylinder and "
    "put it on the green box. Then he should take the red box and put it on the yellow one.")
# abbreviations
add(T, TAB(RED, GREEN),
    "pls put red box on green box thx")
# wish / question
add(T, TAB(BLUE, YEL, hand="left"),
    "Would it be possible for him to stack the blue box on the yellow box with his left "
    "hand?")
# correction
add(T, TAB(BLUE, YEL),
    "put the red box -- sorry, the blue box -- on the yellow one")

ambiguous(T,
          # box003 and cylinder005 are blue
          "pick up the blue one",
          # box002 and sphere006 are green
          "put the green thing on the yellow box",
          # four boxes
          "stack the box on the cylinder")

error(T,
      "pour the water into the cup",
      # no purple object
      "put the purple box on the red box",
      "throw the ball at the wall")


if __name__ == "__main__":
    for line in LINES:
        print(json.dumps(line))
