"""Independent held-out command set "people_f" for simhuman's offline planner.

Written by a helper session (corpus writer F) on 2026-11-28.  Every expected plan was
written by hand BEFORE any run through the planner, from the plan conventions of the
UniHSI paper (Tables 5-9), docs/FORMATS.md (plan format, object parts, built-in scene
table, get-close stand points, object-object pairs; not its "Language commands"
section) and the "Conventions applied" sections of people_c/README.md and
people_e/README.md.  The planner sources, the corpus, the language suite and the
commands of sets A-E were not read.  The pair helpers below re-implement those of
write_people_e.py's header (the same pairs as write_people_b.py).

Imagined users (none used by sets A-E): a text-adventure (interactive fiction) player,
a viewer typing Twitch-style chat commands, a German speaker translating word for
word, a French speaker translating word for word, a learner whose first language puts
the topic first ("Red box, pick up."), an elderly letter-writer (very polite, at
length, signing off), a portrait photographer posing a model, someone using aviation
radio phraseology, a technical writer in the passive voice / third person, a
puzzle-game hint writer, a dance teacher counting beats, an Irish-English speaker, a
guided-relaxation script, a frustrated user repeating themselves in capitals, a game
tester writing "Expected:" lines of bug reports, a product manager writing user
stories, a furniture-showroom salesperson, a recipe writer, and a "Simon says" player.

Run:  python3 write_people_f.py > people_f.jsonl
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
# Same pairs as write_people_e.py's (and write_people_b.py's) helpers.  Each returns a
# LIST of pair strings "object|part|joint|contact|direction"; a step is built by "+".
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
    """Standing touch (UniHSI Table 8), right hand unless named."""
    hands = hands or ("right",)
    return [f"{o}|{part}|{h} hand|contact|{d}" for h in hands]


def SEATREACH(o, part, *hands):
    """Seated reach (UniHSI Table 7): hands carry direction none."""
    hands = hands or ("left", "right")
    return [f"{o}|{part}|{h} hand|contact|none" for h in hands]


def TAB(a, b, part="top", d="up", hand="right"):
    """Tabletop pick and place: grasp, then grasp + object-object pair."""
    grasp = [f"{a}|body|{hand} hand|contact|none"]
    return [grasp, grasp + [f"{b}|{part}|@{a}:body|contact|{d}"]]


def GRASP(a, hand="right"):
    return [f"{a}|body|{hand} hand|contact|none"]


# ================================================================ sit_demo
# chair000 chair (0, 0) yaw 0, no arms; human 0.4 m in front of the seat's front edge:
# no get-close step unless a walk is said.
S = "sit_demo"
C = "chair000"

add(S, [SIT(C)],
    "> sit on chair")                                                   # text adventure
add(S, [SIT(C)],
    "!sit chair")                                                       # Twitch chat
add(S, [SIT(C) + KNEE2(C)],
    "Set yourself on the chair and lay the hands on the knees.")        # German literal
add(S, [SIT(C) + LEANB(C)],
    "Put yourself seated on the chair, the back against the backrest.")  # French literal
add(S, [SIT(C), SIT(C) + LEANF(C)],
    "Good morning. Would you be so very kind as to sit down on the chair for me, and "
    "then, when you are comfortable, lean forward a little? Thank you ever so much. "
    "Yours sincerely, Edith")                                           # elderly letter
add(S, [SIT(C), SIT(C) + FOOT(C, "right", "left")],
    "Okay lovely, pop down onto the chair for me... gorgeous... now cross your right "
    "foot over your left knee. Hold it. Perfect.")                      # photographer
add(S, [GC(C), SIT(C)],
    "Avatar, this is control. Proceed to the chair and take a seat. Over.")  # radio
add(S, [SIT(C)],
    "The chair is to be sat on by the avatar.")                         # passive
add(S, [SIT(C), SIT(C) + LEANB(C)],
    "Right, counts in: five, six, seven, eight, and sit on the chair, two, three, four, "
    "and lean back, six, seven, eight.")                                # dance teacher
add(S, [SIT(C) + KNEE2(C)],
    "Go on and sit yourself down there on the chair and put your two hands on your "
    "knees, sure you're grand.")                                        # Irish English
add(S, [SIT(C), SIT(C) + STOM(C, "left", "right")],
    "Simon says sit on the chair. Simon says put both hands on your stomach.")  # Simon says
add(S, [SIT(C) + LEANF(C)],
    "As a user, I want the avatar to sit on the chair and lean forward, so that it looks "
    "like it is reading.")                                              # user story
add(S, [SIT(C) + KNEE1(C, "left")],
    "Expected result: the character sits on the chair with its left hand resting on its "
    "left knee.")                                                       # bug report
add(S, [SIT(C), SIT(C) + LEANB(C)],
    "Allow yourself to sink slowly down onto the chair... now let your back rest against "
    "the backrest... good, just breathe.")                              # guided relaxation
add(S, [SIT(C)],
    "ugh. SIT. ON. THE. CHAIR. how hard is that")                       # frustrated
add(S, [SIT(C), SIT(C) + KNEE1(C, "right")],
    "The chair, please sit on it, then right hand put on right knee.")  # topic first
add(S, [GC(C), SIT(C), SIT(C) + STOM(C, "left", "right")],
    "Method: walk to the chair. Sit down on it. Fold both hands over your stomach. Leave "
    "to rest for five minutes.")                                        # recipe

error(S,
      "> lie on sofa",                                                  # no sofa
      "Lay the elbows on the armrests of the chair.",                   # armless chair
      "just do a cartwheel already")                                    # unknown action

# ================================================================ living_room
# chair000 (0.95, 0) 0; table001 (2.2, 0) 180; laptop002 on the table; bed003 (4.2, -2.5)
# 90; armchair004 (0, 2.5) -90 (red); sofa005 (-2.5, 0) 0; stool006 (-0.5, -2.5).
# Human (4.0, -1.35): bed 0.4 m (no step); every other object more than 1 m away.
# From the table's front stand point (1.375, 0) chair000's seat is 0.2 m away.
S = "living_room"
CH, TB, LP, BD, AC, SF, ST = ("chair000", "table001", "laptop002", "bed003",
                              "armchair004", "sofa005", "stool006")

add(S, [LIE(BD)],
    "> lie on bed")                                                     # text adventure
add(S, [GC(SF)],
    "> go to sofa")                                                     # text adventure
add(S, [GC(AC), SIT(AC)],
    "!sit armchair")                                                    # Twitch chat
add(S, [GC(SF), SIT(SF), SIT(SF) + LEANB(SF)],
    "Go to the sofa and set yourself on it, then lean yourself backwards.")  # German
add(S, [LIE(BD) + KNEEUP(BD, "left", "right")],
    "Lay yourself on the bed and make both knees high.")                # German
add(S, [GC(AC), SIT(AC) + HANDARM2(AC)],
    "Go until the armchair and put yourself seated, the two hands on the armrests.")  # French
add(S, [LIE(BD) + SIDE(BD, "left")],
    "Lie yourself on the bed and put you on the left side.")            # French
add(S, [GC(AC), SIT(AC) + ELBOW2(AC)],
    "Dear Sir or Madam, I should be most grateful if the young man could make his way "
    "across to the red armchair and sit in it with his elbows resting on the arms. With "
    "kind regards, Harold Pemberton")                                   # elderly letter
add(S, [LIE(BD) + HPILLOW(BD, "left")],
    "Hello dear, I do hope you are keeping well. If it isn't too much bother, could you "
    "lie down on the bed and rest your left hand on the pillow? Thank you kindly.")  # elderly
add(S, [GC(SF), SIT(SF) + ELBOW2(SF)],
    "Right, let's try the sofa. Walk over, sink down into it, both elbows up on the "
    "armrests... lovely, hold that.")                                   # photographer
add(S, [GC(ST), SIT(ST) + KNEE2(ST)],
    "Okay, over to the little stool for me, perch right on it, hands resting on your "
    "knees. Beautiful.")                                                # photographer
add(S, [GC(BD), LIE(BD) + KNEEUP(BD, "left", "right")],
    "Control to avatar: proceed direct to the bed, lie down, knees up, how copy?")  # radio
add(S, [GC(SF), SIT(SF), SIT(SF) + LEANF(SF)],
    "Avatar, proceed to the sofa, sit, lean forward, over.")            # radio
add(S, [LIE(BD) + HPILLOW(BD, "left", "right")],
    "The bed is to be lain on by the character, with both hands placed on the pillow.")  # passive
add(S, [GC(TB), SIT(CH) + SEATREACH(LP, "keyboard")],
    "The avatar walks over to the table and is then seated on the chair in front of the "
    "laptop, where it types.")                                          # third person
add(S, [GC(AC), SIT(AC) + HANDARM1(AC, "right")],
    "Hint: the armchair looks comfy. Try sitting in it and putting your right hand on the "
    "right armrest.")                                                   # puzzle hint
add(S, [GC(SF), SIT(SF), SIT(SF) + FOOT(SF, "left", "right")],
    "Five, six, seven, eight, walk to the sofa, and one, sit, and three, cross your left "
    "foot over your right knee.")                                       # dance teacher
add(S, [GC(SF), SIT(SF) + LEANB(SF)],
    "Would you ever go over and sit on the sofa there and lean back, you must be "
    "wrecked.")                                                         # Irish English
add(S, [GC(AC), SIT(AC), SIT(AC) + HANDARM2(AC)],
    "Walk slowly over to the armchair. Lower yourself into it. Let both hands rest heavy "
    "on the armrests.")                                                 # guided relaxation
add(S, [LIE(BD), HEADUP(BD)],
    "Lie back on the bed... and now, very gently, lift your head off the pillow.")  # guided
add(S, [GC(AC), SIT(AC)],
    "NO. the ARMCHAIR. go sit in the armchair. not the sofa!!")         # frustrated
add(S, [GC(SF), SIT(SF) + HANDARM2(SF)],
    "Expected behaviour: avatar crosses to the sofa and sits with both hands on the "
    "armrests.")                                                        # bug report
add(S, [LIE(BD) + SIDE(BD, "right")],
    "As a tired user, I want my avatar to lie down on the bed on its right side so that "
    "it can nap.")                                                      # user story
add(S, [GC(AC), SIT(AC) + LEANB(AC)],
    "Go on, have a go on the armchair, sink right down into it and lean back. Feel that "
    "lumbar support? Lovely.")                                          # showroom
add(S, [GC(SF), SIT(SF), GC(SF), GC(BD), LIE(BD)],
    "Sit on the sofa first, then come over and lie down on the bed to compare.")  # showroom
add(S, [GC(SF), GC(AC), SIT(AC)],
    "Sofa, go there first. After, the armchair, sit down.")             # topic first
add(S, [GC(CH), SIT(CH) + SEATREACH(LP, "keyboard")],
    "Both hands of the avatar should be placed on the laptop keyboard while it is seated "
    "on the chair.")                                                    # passive

ambiguous(S,
          "Now sit on the brown one for me, darling.",                  # chair000 / stool006
          "Ah go on, sit yourself down in it there.",                   # "it": no referent
          "Would you kindly sit in the seat with the arms on it?")      # armchair / sofa
error(S,
      "> open fridge",                                                  # no fridge
      "Switch the television on and set yourself on the sofa.",         # no television
      "Avatar, climb onto the roof of the building, over.")             # impossible

# ================================================================ office
# table000 (1.8, 0) 180; laptop001 on it; chair002 (0.8, 0) 0 (0.94 m: no step);
# high_stool003 (1.0, 1.8) (black, no back, no arms); box004 (2.0, -1.6) (orange).
# Human (0, -1).  High stool and box more than 1 m away.
S = "office"
TB, LP, CH, HS, BX = "table000", "laptop001", "chair002", "high_stool003", "box004"

add(S, [SIT(CH)],
    "> sit on chair")                                                   # text adventure
add(S, [SIT(CH), SIT(CH) + SEATREACH(LP, "keyboard")],
    "!sit chair then type")                                             # Twitch chat
add(S, [SIT(CH) + SEATREACH(LP, "keyboard", "left", "right")],
    "Set yourself on the chair at the writing desk and type on the laptop with both "
    "hands.")                                                           # German
add(S, [GC(HS), SIT(HS) + KNEE2(HS)],
    "Go until the high stool and sit yourself on it, the hands on the knees.")  # French
add(S, [SIT(CH) + SEATREACH(LP, "keyboard", "right")],
    "I wonder, dear, whether you might sit at the desk and do a little typing on the "
    "laptop with just your right hand. My late husband always typed that way. Thank "
    "you.")                                                             # elderly letter
add(S, [GC(BX), REACH(BX, "top", "up", "left"), GC(CH), SIT(CH)],
    "Avatar, control. Proceed to the box, touch the top with your left hand, then return "
    "to the chair and sit. Over.")                                      # radio
add(S, [GC(HS), SIT(HS)],
    "The high stool is to be sat upon by the character.")               # passive
add(S, [GC(HS), SIT(HS), SIT(HS) + KNEE2(HS)],
    "Five, six, seven, eight: walk to the high stool, hop up onto it, and rest both hands "
    "on your knees.")                                                   # dance teacher
add(S, [SIT(CH) + SEATREACH(LP, "keyboard")],
    "Sit yourself down at the desk there and give the laptop a bit of a type, would "
    "you.")                                                             # Irish English
add(S, [GC(BX), REACH(BX, "top", "up")],
    "for the LAST time: walk to the box and touch it. the BOX. not the stool.")  # frustrated
add(S, [SIT(CH), SIT(CH) + LEANB(CH)],
    "Expected: character sits in the desk chair, leans back against the backrest.")  # bug report
add(S, [GC(BX), REACH(BX, "top", "up", "left", "right")],
    "As a product owner I want the avatar to walk over to the orange box and put both "
    "hands on top of it.")                                              # user story
add(S, [GC(HS), SIT(HS), GC(HS), GC(BX), REACH(BX, "top", "up", "left")],
    "High stool, go and sit. Then the box, touch with left hand.")      # topic first
add(S, [SIT(CH) + LEANB(CH)],
    "Try out this desk chair: sit down and lean right back, feel how it tilts.")  # showroom
add(S, [SIT(CH), SIT(CH) + KNEE1(CH, "right"), GC(CH)],
    "Simon says sit on the chair. Simon says put your right hand on your right knee. "
    "Simon says stand up.")                                             # Simon says
add(S, [SIT(CH), SIT(CH) + SEATREACH(LP, "keyboard", "left", "right")],
    "Method: sit on the desk chair; place both hands on the laptop keyboard; type until "
    "done.")                                                            # recipe

ambiguous(S,
          "!sit",                                                       # chair / high stool
          "Go there and touch it with the hand.")                       # no referent
error(S,
      "> turn on printer",                                              # no printer
      "Perch on the high stool and lean back against it, gorgeous.",    # stool has no back
      "As a user I want the avatar to make me a coffee.")               # unknown action

# ================================================================ bedroom
# bed000 (2.5, 0) 180; stool001 (2.9, 1.5); chair002 (0, 2.2) -90; box003 (-1.2, -1.5).
# Human (0, 0): every object more than 1 m away.  Stool and chair are brown.
S = "bedroom"
BD, ST, CH, BX = "bed000", "stool001", "chair002", "box003"

add(S, [GC(BD), LIE(BD)],
    "> lie on bed")                                                     # text adventure
add(S, [GC(ST), SIT(ST)],
    "!sit stool")                                                       # Twitch chat
add(S, [GC(BD), LIE(BD) + SIDE(BD, "left")],
    "Lay yourself in the bed on the left side.")                        # German
add(S, [GC(CH), SIT(CH), SIT(CH) + STOM(CH, "left", "right")],
    "Go to the chair, set yourself, and lay the hands on the belly.")   # German
add(S, [GC(BD), SITBED(BD), LIE(BD)],
    "Sit yourself on the border of the bed, then lie yourself down.")   # French
add(S, [GC(BD), LIE(BD) + KNEEUP(BD, "left", "right")],
    "Good evening. I'm afraid my eyesight isn't what it was, so please forgive the "
    "typing. Could the lady lie down on the bed and raise both her knees? I would be "
    "most obliged.")                                                    # elderly letter
add(S, [GC(BD), LIE(BD), HEADUP(BD)],
    "Avatar, proceed to the bed, lie down, then lift your head off the pillow. Over and "
    "out.")                                                             # radio
add(S, [GC(ST), SIT(ST), GC(ST), GC(CH)],
    "The stool is sat on by the avatar, after which the chair is walked to.")  # passive
add(S, [GC(BD), LIE(BD), LIE(BD) + HPILLOW(BD, "left", "right")],
    "Make your way to the bed. Lie down. Now let both hands rest softly on the "
    "pillow.")                                                          # guided relaxation
add(S, [GC(BD), SITBED(BD)],
    "the bed. sit on the EDGE of the bed. do NOT lie down.")            # frustrated
add(S, [GC(BX), REACH(BX, "top", "up", "right")],
    "Expected: avatar walks to the box and taps its top with the right hand.")  # bug report
add(S, [GC(ST), SIT(ST) + KNEE2(ST)],
    "As a parent I want the avatar to sit on the little stool next to the bed with both "
    "hands on its knees.")                                              # user story
add(S, [GC(BD), SITBED(BD), GC(BD), GC(ST), SIT(ST)],
    "Bed, first sit on the edge. Then stool, go sit.")                  # topic first
add(S, [GC(BD), LIE(BD) + FOOTLIE(BD, "right", "left")],
    "Go over and lie on the bed there and put your right foot up on your left knee, "
    "you're grand.")                                                    # Irish English
add(S, [GC(CH), SIT(CH), SIT(CH) + LEANF(CH)],
    "Simon says walk to the chair. Simon says sit down on it. Simon says lean "
    "forward.")                                                         # Simon says
add(S, [GC(BD), SITBED(BD), LIE(BD) + KNEEUP(BD, "left")],
    "Okay, perch on the edge of the bed for me... lovely... now lie back and bring your "
    "left knee up.")                                                    # photographer

ambiguous(S,
          "Would you be a dear and take a seat? Thank you.",            # bed / stool / chair
          "sit on the brown one, I said!",                              # stool / chair
          "That one, please go and sit.")                               # no referent
error(S,
      "> open wardrobe",                                                # no wardrobe
      "Make the bed.",                                                  # unknown action
      "As a user I want the avatar to jump on the bed like a trampoline.")  # unknown action

# ================================================================ tabletop_demo
# table000 (1.0, 0) 180; box001 red, box002 green (tall), box003 blue, box004 yellow
# (flat), cylinder005 blue, sphere006 green.  Human (0.2, 0): all within 1 m.
S = "tabletop_demo"
RED, GREEN, BLUE, YEL, CYL, BALL = ("box001", "box002", "box003", "box004",
                                    "cylinder005", "sphere006")

add(S, TAB(RED, YEL),
    "> put red block on yellow block")                                  # text adventure
add(S, [GRASP(BALL)],
    "> get ball")                                                       # text adventure
add(S, TAB(RED, YEL),
    "!stack red yellow")                                                # Twitch chat
add(S, TAB(BALL, YEL),
    "Lay the ball onto the yellow box.")                                # German
add(S, TAB(RED, CYL, hand="left"),
    "Put the red cube on top of the blue cylinder, with the left hand.")  # French
add(S, TAB(BALL, YEL),
    "Dear helper, might I trouble you to pick up the little green ball and set it down "
    "very carefully on the flat yellow box? I thank you in advance. Margaret")  # elderly
add(S, TAB(BALL, CYL),
    "Hint: the ball wants to sit on the cylinder.")                     # puzzle hint
add(S, TAB(RED, GREEN),
    "Stuck? Try putting the red block on the tall green block.")        # puzzle hint
add(S, TAB(CYL, YEL),
    "Avatar, pick up the blue cylinder, place it on the yellow box, over.")  # radio
add(S, TAB(RED, YEL),
    "Red box, pick up. Yellow box, put on top.")                        # topic first
add(S, TAB(BALL, YEL),
    "ok the BALL goes on the YELLOW box. not the red one. the yellow one.")  # frustrated
add(S, TAB(BALL, CYL),
    "Expected: character grabs the sphere with its right hand and puts it on the blue "
    "cylinder.")                                                        # bug report
add(S, TAB(RED, YEL) + TAB(BALL, CYL),
    "As a user I want the avatar to stack the red box on the yellow box and then the "
    "green ball on the blue cylinder.")                                 # user story
add(S, TAB(RED, YEL),
    "Pick up that red yoke there and stick it on top of the yellow one.")  # Irish English
add(S, [GRASP(BLUE, "left")],
    "Simon says pick up the blue box with your left hand.")             # Simon says

ambiguous(S,
          "> take blue",                                                # box003 / cylinder005
          "Lay the green one onto the red box.",                        # box002 / sphere006
          "just grab the box already",                                  # four boxes
          "Would you be so kind as to put it on the yellow box, dear?")  # no referent
error(S,
      "Avatar, take a seat, over.",                                     # no seat
      "Hint: the purple pyramid goes on the red box.",                  # no such object
      "> lie on table")                                                 # table: no mattress


# ---------------------------------------------------------------- self-check
# Object ids and types of the built-in scenes (docs/FORMATS.md, "Built-in scenes").
SCENES = {
    "sit_demo": {"chair000": "chair"},
    "living_room": {"chair000": "chair", "table001": "table", "laptop002": "laptop",
                    "bed003": "bed", "armchair004": "armchair", "sofa005": "sofa",
                    "stool006": "stool"},
    "office": {"table000": "table", "laptop001": "laptop", "chair002": "chair",
               "high_stool003": "high_stool", "box004": "box"},
    "bedroom": {"bed000": "bed", "stool001": "stool", "chair002": "chair", "box003": "box"},
    "tabletop_demo": {"table000": "table", "box001": "box", "box002": "box", "box003": "box",
                      "box004": "box", "cylinder005": "cylinder", "sphere006": "sphere"},
}
PARTS = {
    "chair": {"seat surface", "back surface"},
    "armchair": {"seat surface", "back surface", "left arm", "right arm"},
    "sofa": {"seat surface", "back surface", "left arm", "right arm"},
    "stool": {"seat surface"}, "high_stool": {"seat surface"},
    "bed": {"mattress", "pillow"}, "table": {"board"}, "laptop": {"keyboard", "screen"},
    "box": {"top", "left side", "right side", "front side", "back side", "body"},
    "cylinder": {"top", "body"}, "sphere": {"body"},
}
JOINTS = {"pelvis", "torso", "head", "left shoulder", "left elbow", "left hand",
          "right shoulder", "right elbow", "right hand", "left hip", "left knee", "left foot",
          "right hip", "right knee", "right foot"}
MOVABLE = {"box", "cylinder", "sphere"}


def check():
    for n, line in enumerate(LINES, 1):
        objs = SCENES[line["scene"]]
        for step in line.get("expect", []):
            assert step, (n, "empty step")
            for pair in step:
                o, part, joint, contact, d = pair.split("|")
                assert o in objs, (n, pair)
                assert d in {"up", "down", "front", "back", "left", "right", "none"}, (n, pair)
                if part == "none":
                    assert joint == "none" and contact == "none" and d != "none", (n, pair)
                    continue
                assert contact in {"contact", "not contact", "not care"}, (n, pair)
                assert part in PARTS[objs[o]] or part in JOINTS, (n, pair)
                if joint.startswith("@"):
                    sub, sub_part = joint[1:].split(":")
                    assert sub in objs and sub != o and objs[sub] in MOVABLE, (n, pair)
                    assert sub_part in PARTS[objs[sub]], (n, pair)
                else:
                    assert joint in JOINTS and joint != part, (n, pair)
        kinds = [k for k in ("expect", "expect_ambiguous", "expect_error") if k in line]
        assert len(kinds) == 1, (n, kinds)


check()
for line in LINES:
    print(json.dumps(line))
