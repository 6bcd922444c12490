"""Independent held-out command set "people_e" for simhuman's offline planner.

Written by a helper session (corpus writer E) on 2026-11-28.  Every expected plan was
written by hand BEFORE any run through the planner, from the plan conventions of the
UniHSI paper (Tables 5-9), docs/FORMATS.md (plan format, built-in scene table,
get-close stand points; not its "Language commands" section) and the "Conventions
applied" section of people_c/README.md.  The planner sources, the corpus, the
language suite and the commands of sets A-D were not read.  The pair helpers below
re-implement those of write_people_b.py (its lines 1-141) with the same pairs.

Imagined users (none used by sets A-D): a dungeon master narrating to players, a
military drill instructor, a museum / VR tour guide, an occupational therapist
writing daily-living assessments, a hotel concierge, a speech-to-text user with
homophone errors, a programmer writing pseudo-code or JSON-ish strings, an
Indian-English speaker, a Singaporean-English speaker, a poet, a terse SMS user,
someone who asks rhetorical questions, a caregiver for an elderly parent, an
esports caster, and a screenwriter writing present-tense action lines.

Run:  python3 write_people_e.py > people_e.jsonl
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
# Same pairs as write_people_b.py's helpers.  Each returns a LIST of pair strings
# "object|part|joint|contact|direction"; a step is built by "+".
def GC(o, side="front"):
    return [f"{o}|none|none|none|{side}"]


def SIT(o):
    return [f"{o}|seat surface|pelvis|contact|up"]


def SITBED(o):
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|not contact|up"]


def LIE(o):
    return [f"{o}|mattress|pelvis|contact|up", f"{o}|pillow|head|contact|up"]


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


# ================================================================ sit_demo
# chair000 chair (0, 0) yaw 0; human 0.4 m in front of the seat edge: no get-close.
S = "sit_demo"
C = "chair000"
# dungeon master
add(S, [SIT(C)], "You spot a lone wooden chair behind you. You sit upon it.")
# drill instructor
add(S, [SIT(C), SIT(C) + KNEE2(C)], "Sit down on that chair, recruit! Hands on your knees!")
add(S, [SIT(C) + LEANB(C)], "Recruit, sit on that chair and lean back against the backrest, double time!")
# occupational therapist
add(S, [SIT(C), GC(C)], "Sit-to-stand assessment: client sits on the chair, then stands up.")
add(S, [SIT(C) + KNEE1(C, "right")], "Client seated on the chair with right hand resting on right knee.")
# hotel concierge
add(S, [SIT(C) + FOOT(C, "right", "left")],
    "Please have a seat on the chair and do feel free to cross your right foot over your left knee.")
# speech-to-text homophone (than -> then)
add(S, [SIT(C), SIT(C) + LEANB(C)], "sit on the chair than lean back")
# programmer
add(S, [SIT(C), SIT(C) + LEANF(C)], 'sit(chair000); lean("forward");')
add(S, [SIT(C) + STOM(C, "left", "right")], '{"action": "sit", "target": "chair", "hands": "stomach"}')
# Indian English
add(S, [SIT(C) + KNEE1(C, "left")], "Kindly be seated on the chair and keep your left hand on your left knee itself.")
# Singaporean English
add(S, [SIT(C), SIT(C) + FOOT(C, "left", "right")],
    "Sit on the chair first, then put your left foot on your right knee lah.")
# poet
add(S, [SIT(C) + LEANB(C)], "Rest upon the humble chair and let thy weary back recline against its frame.")
# terse SMS
add(S, [SIT(C) + LEANF(C)], "sit n lean fwd")
# rhetorical question
add(S, [SIT(C)], "Wouldn't you rather sit down on that chair?")
# caregiver
add(S, [SIT(C), SIT(C) + KNEE2(C)],
    "Alright Dad, sit yourself down on the chair, then pop both hands on your knees, there you go.")
# esports caster
add(S, [SIT(C), SIT(C) + LEANB(C), GC(C)], "He sits down, leans back, and then he's up on his feet again!")
# screenwriter
add(S, [SIT(C), SIT(C) + STOM(C, "left", "right")],
    "MARA turns, sits in the chair, and rests both hands on her stomach.")

error(S, "You collapse onto the sofa.")                 # no sofa
error(S, "Drop and give me twenty push-ups, recruit!")  # no such action
error(S, "open window pls")                             # no window

# ================================================================ living_room
# human (4.0, -1.35): bed003 0.4 m (no get-close); every other object > 1 m.
S = "living_room"
B, CH, LP, AC, SO, ST = "bed003", "chair000", "laptop002", "armchair004", "sofa005", "stool006"
# bed, no walk
add(S, [LIE(B)], "Exhausted from the dungeon, you lie down on the bed behind you, head upon the pillow.")
add(S, [SITBED(B), LIE(B)], "Okay Gran, sit on the edge of the bed first, then lie back with your head on the pillow.")
add(S, [LIE(B) + KNEEUP(B, "left", "right")], "Supine on bed, both knees flexed up.")
add(S, [LIE(B) + SIDE(B, "left")], "Lay thee down upon the bed and turn upon thy left side.")
add(S, [LIE(B), LIE(B) + HPILLOW(B, "left", "right")], "Lie on the bed then put both hands on the pillow can?")
add(S, [LIE(B) + FOOTLIE(B, "right", "left")], "lie down on the bad with your right foot on your left knee")
add(S, [HEADUP(B)], "ROSA lies down on the bed, her head raised off the pillow.")
# sofa
add(S, [GC(SO), SIT(SO)], "Do take a seat on the sofa, madam.")
add(S, [GC(SO), SIT(SO) + ELBOW2(SO)], "Go and sit on the sofa and keep your both elbows on the armrests.")
add(S, [GC(SO), SIT(SO), SIT(SO) + LEANB(SO)],
    "Next, please walk over to the sofa, take a seat, and lean back to admire the ceiling.")
add(S, [GC(SO), SIT(SO), SIT(SO) + LEANB(SO)], "couch. sit. lean back")
# armchair
add(S, [GC(AC), SIT(AC) + HANDARM2(AC)],
    "You stride across the room to the red armchair and sink into it with your hands upon its arms.")
add(S, [GC(AC), SIT(AC), SIT(AC) + ELBOW1(AC, "left"), GC(AC)],
    "Assess: client walks to armchair, sits, places left elbow on left armrest, then stands.")
add(S, [GC(AC), SIT(AC) + HANDARM1(AC, "right")],
    "Why don't you go and sit in the armchair with your right hand on the right armrest?")
add(S, [GC(AC), SIT(AC), SIT(AC) + HANDOFF(AC)], "armchair004.sit(); armchair004.hands_off_armrests();")
# stool
add(S, [GC(ST), SIT(ST), SIT(ST) + KNEE2(ST)], "Stool! Sit on it! Hands on your knees!")
add(S, [GC(ST), SIT(ST) + STOM(ST, "left", "right")],
    "Mum, sit on the little stool for a minute and rest your hands on your tummy.")
# chair and laptop (seated reach)
add(S, [GC(CH), SIT(CH), SIT(CH) + SEATREACH(LP, "keyboard")],
    "LEO crosses to the desk chair and sits. He types on the laptop.")
add(S, [GC(CH), SIT(CH), SIT(CH) + SEATREACH(LP, "keyboard")],
    "Please sit on the chair near the table, then do some typing on the laptop.")
add(S, [GC(CH), SIT(CH), SIT(CH) + SEATREACH(LP, "keyboard", "right")],
    "Player walks to the chair, sits down, and reaches for the laptop's keyboard with his right hand!")
# several objects: stand up (get-close to the seat or bed), walk, act
add(S, [LIE(B), GC(B), GC(AC), SIT(AC)],
    "You lie down on the bed to rest. At dawn you rise, walk to the armchair and sit.")
add(S, [SITBED(B), GC(B), GC(AC), SIT(AC) + LEANB(AC)],
    "First sit on the edge of the bed, then get up, go to the armchair and sit there leaning back.")
add(S, [GC(ST), SIT(ST), GC(ST), GC(SO), SIT(SO)],
    "Begin at the stool, where you may sit; then proceed to the sofa and sit once more.")
add(S, [GC(SO), SIT(SO), GC(SO), GC(CH), SIT(CH)],
    "walk_to('sofa005'); sit('sofa005'); stand(); walk_to('chair000'); sit('chair000')")
add(S, [GC(SO), SIT(SO), GC(SO), GC(B), LIE(B)], "sit on sofa then go lie on bed")
add(S, [GC(ST), SIT(ST)], "Isn't it about time you walked over to the stool and sat down?")

ambiguous(S, "Please have a seat.")                     # chair, armchair, sofa, stool, bed
ambiguous(S, "Rest your hands on the armrests.")        # armchair or sofa
ambiguous(S, "walk over to it")                         # no antecedent
error(S, "Turn on the television, would you?")
error(S, "Open the fridge and grab a drink.")
error(S, "You climb the bookshelf to reach the top shelf.")

# ================================================================ office
# human (0, -1): chair002 0.94 m (no get-close); table000, laptop001, high_stool003,
# box004 all > 1 m.
S = "office"
CH, LP, HS, BX, TB = "chair002", "laptop001", "high_stool003", "box004", "table000"
add(S, [SIT(CH) + SEATREACH(LP, "keyboard")], "Client sits at the desk chair and types on the laptop with both hands.")
add(S, [SIT(CH), SIT(CH) + SEATREACH(LP, "keyboard")], "Sit down in that chair! Hands on the keyboard!")
add(S, [SIT(CH) + LEANB(CH)], "Please take a seat in the office chair and lean back — make yourself comfortable.")
add(S, [GC(HS), SIT(HS)], "Please go and sit on the high stool only.")
add(S, [GC(HS), SIT(HS), GC(HS), GC(CH), SIT(CH)], "Go sit on the bar stool first, after that sit on the chair lah.")
add(S, [GC(BX), REACH(BX, "top", "up", "left")], "goto(box004); touch(box004.top, hand='left')")
add(S, [GC(HS), SIT(HS)], "Ascend the tall stool and perch upon it like a heron.")
add(S, [SIT(CH), SIT(CH) + KNEE2(CH)], "sit chair, hands on knees")
add(S, [SIT(CH) + STOM(CH, "left")], "Why not sit down on the chair and rest your left hand on your stomach?")
add(S, [GC(BX), REACH(BX, "top", "up", "left", "right")],
    "Dad, walk over to the box, put both hands on top of it for balance.")
add(S, [GC(HS), SIT(HS), SIT(HS) + FOOT(HS, "left", "right")],
    "He heads straight for the high stool, sits, and crosses his left foot over his right knee!")
add(S, [SIT(CH), SIT(CH) + LEANB(CH), GC(CH), GC(BX)],
    "ANNA sits at the desk chair. Leans back. Then, she gets up and walks to the box.")
add(S, [GC(BX), REACH(BX, "top", "up")], "If you'd like, walk to the box in the corner and touch its lid.")
add(S, [SIT(CH) + LEANF(CH)], "You settle onto the chair before the desk and lean forward over the glowing laptop.")
add(S, [SIT(CH), SIT(CH) + FOOT(CH, "right", "left"), GC(CH)],
    "Sit on chair, right foot on left knee, hold 10 s; then stand.")
add(S, [GC(BX)], "Double time to the box, recruit!")

ambiguous(S, "Go over there and sit.")   # chair or high stool, no antecedent
ambiguous(S, "Touch the top.")           # box top or table top
error(S, "Lie down on the bed.")         # no bed
error(S, "Print the quarterly report.")
error(S, "Pick up the phone and call the front desk, please.")

# ================================================================ bedroom
# human (0, 0): bed000 1.75 m, stool001, chair002, box003 all > 1 m.
S = "bedroom"
B, ST, CH, BX = "bed000", "stool001", "chair002", "box003"
add(S, [GC(B), SITBED(B), LIE(B)], "Time for bed, love — walk to the bed, sit on the edge, then lie down slowly.")
add(S, [GC(B), LIE(B), LIE(B) + SIDE(B, "right")], "Bed mobility: supine on bed, roll to right side.")
add(S, [GC(B), LIE(B) + HPILLOW(B, "left", "right")],
    "Weary adventurer, you lie down upon the inn's bed with both hands resting on the pillow.")
add(S, [GC(B), LIE(B) + KNEEUP(B, "left")], "Go and lie down on the bed with your left knee up.")
add(S, [GC(B), LIE(B), LIE(B) + KNEEUP(B, "left", "right")], "Lie on the bed, then lift up both knees.")
add(S, [GC(ST), SIT(ST), GC(ST), GC(B), LIE(B)], "Upon the stool, a moment's rest; then to the bed, and sleep.")
add(S, [GC(CH), SIT(CH)], "go 2 chair n sit")
add(S, [GC(CH), SIT(CH) + KNEE2(CH)], "Don't you want to sit on the chair and put your hands on your knees?")
add(S, [GC(CH), SIT(CH), SIT(CH) + LEANB(CH)],
    "for step in ['walk chair002', 'sit chair002', 'lean back']: do(step)")
add(S, [GC(B), LIE(B) + HPILLOW(B, "right")], "lay on the bed with your write hand on the pillow")
add(S, [GC(BX), REACH(BX, "top", "up", "left")], "He sprints to the box and slaps the top of it with his left hand!")
add(S, [GC(ST), SIT(ST), SIT(ST) + KNEE1(ST, "right")],
    "SAM crosses to the stool and sits. He rests his right hand on his right knee.")
add(S, [GC(B), SITBED(B), LIE(B) + FOOTLIE(B, "left", "right")],
    "Welcome to your room, madam. Perhaps sit on the bed first, then lie down with your left foot over your right knee.")
add(S, [GC(CH), SIT(CH), GC(CH), GC(B)],
    "From here, walk to the chair by the wall, sit, and then get up and head over to the bed.")
add(S, [GC(B), LIE(B), HEADUP(B)], "Bed! Lie down! Head off the pillow!")
add(S, [GC(CH), SIT(CH), SIT(CH) + LEANF(CH)],
    "You wander to the old wooden chair, sit, and lean forward to listen closely.")

ambiguous(S, "Sit down.")          # bed, stool or chair
ambiguous(S, "Sit on the seat.")   # stool or chair
error(S, "Sit on the sofa.")       # no sofa
error(S, "Open the wardrobe and hang up your coat.")
error(S, "Type on the laptop for a while.")  # no laptop

# ================================================================ tabletop_demo
# human (0.2, 0) standing; everything within 1 m: no get-close.
# box001 red, box002 green, box003 blue, box004 yellow (flat), cylinder005 blue,
# sphere006 green.
S = "tabletop_demo"
R, G, BL, Y, CY, SP = "box001", "box002", "box003", "box004", "cylinder005", "sphere006"
add(S, TAB(R, Y, "top", "up"), "stack(box001, on=box004)")
add(S, [GRASP(SP)], "grab green ball")
add(S, TAB(R, Y, "top", "up"), "Pick up the red box! Now put it on the yellow box!")
add(S, TAB(R, CY, "top", "up"), "put the read box on the blew cylinder")
add(S, TAB(SP, Y, "top", "up"), "Kindly keep the green ball on top of the yellow box.")
add(S, TAB(G, CY, "top", "up"), "Take the green box put on top of the blue cylinder can?")
add(S, TAB(SP, Y, "top", "up"), "Lift the verdant sphere and crown the yellow block with it.")
add(S, [GRASP(CY)], "Why not pick up the blue cylinder?")
add(S, [GRASP(Y, "left")], "Now, with your left hand, please lift the yellow box.")
add(S, TAB(R, CY, "top", "up", "left"),
    "Fine motor task: grasp the red block with the left hand and place it on the blue cylinder.")
add(S, TAB(BL, R, "top", "up"), "He grabs the blue box and stacks it right on the red box!")
add(S, TAB(SP, CY, "top", "up"), "KAI picks up the green ball. He sets it down on the blue cylinder.")
add(S, TAB(R, G, "top", "up"), "You seize the crimson block and place it atop the green block.")
add(S, TAB(Y, BL, "top", "up") + TAB(SP, R, "top", "up"),
    "Put the yellow box on the blue box for me, will you? Then the green ball on top of the red box.")
add(S, TAB(CY, Y, "top", "up"), "Might I suggest placing the blue cylinder upon the yellow box?")
add(S, TAB(R, G, "top", "up"), '{"pick": "red box", "place_on": "green box"}')

ambiguous(S, "pick up the box")                          # four boxes
ambiguous(S, "Grab the blue one!")                       # blue box or blue cylinder
ambiguous(S, "Put the green thing on the yellow box.")   # green box or green ball
ambiguous(S, "put the red box on the blue one")          # blue box or blue cylinder
ambiguous(S, "Stack the block on the cylinder.")         # which of four boxes
error(S, "Sit on the chair.")                            # no chair in tabletop_demo
error(S, "Put the purple box on the red box.")           # no purple box
error(S, "Pick up the orange pyramid.")                  # no pyramid

for line in LINES:
    print(json.dumps(line))
