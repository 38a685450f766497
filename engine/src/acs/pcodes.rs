//! The ACS instruction set: every pcode's number and name as `acc` (ZDoom's
//! compiler, `pcode.h`) numbers them, the operands each carries in the code
//! stream, and which of them the VM runs. The loader decodes with
//! [`operands`]; the VM executes what [`supported`] admits.

/// Pcodes are numbered 0..COUNT (`PCODE_COMMAND_COUNT` in acc 1.60).
pub const COUNT: u16 = 385;

/// Names without acc's `PCD_` prefix, indexed by pcode. 129 and 130 are
/// `PCD_LSPEC6`/`PCD_LSPEC6DIRECT` in ZDoom's copy of the list (never
/// emitted by any compiler); acc names them after Skulltag's invasion pcodes.
#[rustfmt::skip]
const NAMES: [&str; COUNT as usize] = [
    "NOP", "TERMINATE", "SUSPEND", "PUSHNUMBER", "LSPEC1", "LSPEC2", "LSPEC3", "LSPEC4",
    "LSPEC5", "LSPEC1DIRECT", "LSPEC2DIRECT", "LSPEC3DIRECT", "LSPEC4DIRECT",
    "LSPEC5DIRECT", "ADD", "SUBTRACT", "MULTIPLY", "DIVIDE", "MODULUS", "EQ", "NE", "LT",
    "GT", "LE", "GE", "ASSIGNSCRIPTVAR", "ASSIGNMAPVAR", "ASSIGNWORLDVAR", "PUSHSCRIPTVAR",
    "PUSHMAPVAR", "PUSHWORLDVAR", "ADDSCRIPTVAR", "ADDMAPVAR", "ADDWORLDVAR",
    "SUBSCRIPTVAR", "SUBMAPVAR", "SUBWORLDVAR", "MULSCRIPTVAR", "MULMAPVAR", "MULWORLDVAR",
    "DIVSCRIPTVAR", "DIVMAPVAR", "DIVWORLDVAR", "MODSCRIPTVAR", "MODMAPVAR", "MODWORLDVAR",
    "INCSCRIPTVAR", "INCMAPVAR", "INCWORLDVAR", "DECSCRIPTVAR", "DECMAPVAR", "DECWORLDVAR",
    "GOTO", "IFGOTO", "DROP", "DELAY", "DELAYDIRECT", "RANDOM", "RANDOMDIRECT",
    "THINGCOUNT", "THINGCOUNTDIRECT", "TAGWAIT", "TAGWAITDIRECT", "POLYWAIT",
    "POLYWAITDIRECT", "CHANGEFLOOR", "CHANGEFLOORDIRECT", "CHANGECEILING",
    "CHANGECEILINGDIRECT", "RESTART", "ANDLOGICAL", "ORLOGICAL", "ANDBITWISE", "ORBITWISE",
    "EORBITWISE", "NEGATELOGICAL", "LSHIFT", "RSHIFT", "UNARYMINUS", "IFNOTGOTO",
    "LINESIDE", "SCRIPTWAIT", "SCRIPTWAITDIRECT", "CLEARLINESPECIAL", "CASEGOTO",
    "BEGINPRINT", "ENDPRINT", "PRINTSTRING", "PRINTNUMBER", "PRINTCHARACTER",
    "PLAYERCOUNT", "GAMETYPE", "GAMESKILL", "TIMER", "SECTORSOUND", "AMBIENTSOUND",
    "SOUNDSEQUENCE", "SETLINETEXTURE", "SETLINEBLOCKING", "SETLINESPECIAL", "THINGSOUND",
    "ENDPRINTBOLD", "ACTIVATORSOUND", "LOCALAMBIENTSOUND", "SETLINEMONSTERBLOCKING",
    "PLAYERBLUESKULL", "PLAYERREDSKULL", "PLAYERYELLOWSKULL", "PLAYERMASTERSKULL",
    "PLAYERBLUECARD", "PLAYERREDCARD", "PLAYERYELLOWCARD", "PLAYERMASTERCARD",
    "PLAYERBLACKSKULL", "PLAYERSILVERSKULL", "PLAYERGOLDSKULL", "PLAYERBLACKCARD",
    "PLAYERSILVERCARD", "ISNETWORKGAME", "PLAYERTEAM", "PLAYERHEALTH", "PLAYERARMORPOINTS",
    "PLAYERFRAGS", "PLAYEREXPERT", "BLUETEAMCOUNT", "REDTEAMCOUNT", "BLUETEAMSCORE",
    "REDTEAMSCORE", "ISONEFLAGCTF", "GETINVASIONWAVE", "GETINVASIONSTATE", "PRINTNAME",
    "MUSICCHANGE", "CONSOLECOMMANDDIRECT", "CONSOLECOMMAND", "SINGLEPLAYER", "FIXEDMUL",
    "FIXEDDIV", "SETGRAVITY", "SETGRAVITYDIRECT", "SETAIRCONTROL", "SETAIRCONTROLDIRECT",
    "CLEARINVENTORY", "GIVEINVENTORY", "GIVEINVENTORYDIRECT", "TAKEINVENTORY",
    "TAKEINVENTORYDIRECT", "CHECKINVENTORY", "CHECKINVENTORYDIRECT", "SPAWN",
    "SPAWNDIRECT", "SPAWNSPOT", "SPAWNSPOTDIRECT", "SETMUSIC", "SETMUSICDIRECT",
    "LOCALSETMUSIC", "LOCALSETMUSICDIRECT", "PRINTFIXED", "PRINTLOCALIZED",
    "MOREHUDMESSAGE", "OPTHUDMESSAGE", "ENDHUDMESSAGE", "ENDHUDMESSAGEBOLD", "SETSTYLE",
    "SETSTYLEDIRECT", "SETFONT", "SETFONTDIRECT", "PUSHBYTE", "LSPEC1DIRECTB",
    "LSPEC2DIRECTB", "LSPEC3DIRECTB", "LSPEC4DIRECTB", "LSPEC5DIRECTB", "DELAYDIRECTB",
    "RANDOMDIRECTB", "PUSHBYTES", "PUSH2BYTES", "PUSH3BYTES", "PUSH4BYTES", "PUSH5BYTES",
    "SETTHINGSPECIAL", "ASSIGNGLOBALVAR", "PUSHGLOBALVAR", "ADDGLOBALVAR", "SUBGLOBALVAR",
    "MULGLOBALVAR", "DIVGLOBALVAR", "MODGLOBALVAR", "INCGLOBALVAR", "DECGLOBALVAR",
    "FADETO", "FADERANGE", "CANCELFADE", "PLAYMOVIE", "SETFLOORTRIGGER",
    "SETCEILINGTRIGGER", "GETACTORX", "GETACTORY", "GETACTORZ", "STARTTRANSLATION",
    "TRANSLATIONRANGE1", "TRANSLATIONRANGE2", "ENDTRANSLATION", "CALL", "CALLDISCARD",
    "RETURNVOID", "RETURNVAL", "PUSHMAPARRAY", "ASSIGNMAPARRAY", "ADDMAPARRAY",
    "SUBMAPARRAY", "MULMAPARRAY", "DIVMAPARRAY", "MODMAPARRAY", "INCMAPARRAY",
    "DECMAPARRAY", "DUP", "SWAP", "WRITETOINI", "GETFROMINI", "SIN", "COS", "VECTORANGLE",
    "CHECKWEAPON", "SETWEAPON", "TAGSTRING", "PUSHWORLDARRAY", "ASSIGNWORLDARRAY",
    "ADDWORLDARRAY", "SUBWORLDARRAY", "MULWORLDARRAY", "DIVWORLDARRAY", "MODWORLDARRAY",
    "INCWORLDARRAY", "DECWORLDARRAY", "PUSHGLOBALARRAY", "ASSIGNGLOBALARRAY",
    "ADDGLOBALARRAY", "SUBGLOBALARRAY", "MULGLOBALARRAY", "DIVGLOBALARRAY",
    "MODGLOBALARRAY", "INCGLOBALARRAY", "DECGLOBALARRAY", "SETMARINEWEAPON",
    "SETACTORPROPERTY", "GETACTORPROPERTY", "PLAYERNUMBER", "ACTIVATORTID",
    "SETMARINESPRITE", "GETSCREENWIDTH", "GETSCREENHEIGHT", "THING_PROJECTILE2", "STRLEN",
    "SETHUDSIZE", "GETCVAR", "CASEGOTOSORTED", "SETRESULTVALUE", "GETLINEROWOFFSET",
    "GETACTORFLOORZ", "GETACTORANGLE", "GETSECTORFLOORZ", "GETSECTORCEILINGZ",
    "LSPEC5RESULT", "GETSIGILPIECES", "GETLEVELINFO", "CHANGESKY", "PLAYERINGAME",
    "PLAYERISBOT", "SETCAMERATOTEXTURE", "ENDLOG", "GETAMMOCAPACITY", "SETAMMOCAPACITY",
    "PRINTMAPCHARARRAY", "PRINTWORLDCHARARRAY", "PRINTGLOBALCHARARRAY", "SETACTORANGLE",
    "GRABINPUT", "SETMOUSEPOINTER", "MOVEMOUSEPOINTER", "SPAWNPROJECTILE",
    "GETSECTORLIGHTLEVEL", "GETACTORCEILINGZ", "SETACTORPOSITION", "CLEARACTORINVENTORY",
    "GIVEACTORINVENTORY", "TAKEACTORINVENTORY", "CHECKACTORINVENTORY", "THINGCOUNTNAME",
    "SPAWNSPOTFACING", "PLAYERCLASS", "ANDSCRIPTVAR", "ANDMAPVAR", "ANDWORLDVAR",
    "ANDGLOBALVAR", "ANDMAPARRAY", "ANDWORLDARRAY", "ANDGLOBALARRAY", "EORSCRIPTVAR",
    "EORMAPVAR", "EORWORLDVAR", "EORGLOBALVAR", "EORMAPARRAY", "EORWORLDARRAY",
    "EORGLOBALARRAY", "ORSCRIPTVAR", "ORMAPVAR", "ORWORLDVAR", "ORGLOBALVAR", "ORMAPARRAY",
    "ORWORLDARRAY", "ORGLOBALARRAY", "LSSCRIPTVAR", "LSMAPVAR", "LSWORLDVAR",
    "LSGLOBALVAR", "LSMAPARRAY", "LSWORLDARRAY", "LSGLOBALARRAY", "RSSCRIPTVAR",
    "RSMAPVAR", "RSWORLDVAR", "RSGLOBALVAR", "RSMAPARRAY", "RSWORLDARRAY", "RSGLOBALARRAY",
    "GETPLAYERINFO", "CHANGELEVEL", "SECTORDAMAGE", "REPLACETEXTURES", "NEGATEBINARY",
    "GETACTORPITCH", "SETACTORPITCH", "PRINTBIND", "SETACTORSTATE", "THINGDAMAGE2",
    "USEINVENTORY", "USEACTORINVENTORY", "CHECKACTORCEILINGTEXTURE",
    "CHECKACTORFLOORTEXTURE", "GETACTORLIGHTLEVEL", "SETMUGSHOTSTATE", "THINGCOUNTSECTOR",
    "THINGCOUNTNAMESECTOR", "CHECKPLAYERCAMERA", "MORPHACTOR", "UNMORPHACTOR",
    "GETPLAYERINPUT", "CLASSIFYACTOR", "PRINTBINARY", "PRINTHEX", "CALLFUNC", "SAVESTRING",
    "PRINTMAPCHRANGE", "PRINTWORLDCHRANGE", "PRINTGLOBALCHRANGE", "STRCPYTOMAPCHRANGE",
    "STRCPYTOWORLDCHRANGE", "STRCPYTOGLOBALCHRANGE", "PUSHFUNCTION", "CALLSTACK",
    "SCRIPTWAITNAMED", "TRANSLATIONRANGE3", "GOTOSTACK", "ASSIGNSCRIPTARRAY",
    "PUSHSCRIPTARRAY", "ADDSCRIPTARRAY", "SUBSCRIPTARRAY", "MULSCRIPTARRAY",
    "DIVSCRIPTARRAY", "MODSCRIPTARRAY", "INCSCRIPTARRAY", "DECSCRIPTARRAY",
    "ANDSCRIPTARRAY", "EORSCRIPTARRAY", "ORSCRIPTARRAY", "LSSCRIPTARRAY", "RSSCRIPTARRAY",
    "PRINTSCRIPTCHARARRAY", "PRINTSCRIPTCHRANGE", "STRCPYTOSCRIPTCHRANGE", "LSPEC5EX",
    "LSPEC5EXRESULT", "TRANSLATIONRANGE4", "TRANSLATIONRANGE5",
];

/// `PCD_` name of a pcode, or "unknown" past the end of the list.
pub fn name(pcode: u16) -> &'static str {
    NAMES.get(usize::from(pcode)).copied().unwrap_or("unknown")
}

/// ZDoom's extended functions reached through `PCD_CALLFUNC`, by id
/// (`ACSF_*` in p_acs.cpp; ids jump to 200, 300, 400 and 19620).
#[rustfmt::skip]
const FUNCTIONS: &[(u16, &str)] = &[
    (1, "GetLineUDMFInt"), (2, "GetLineUDMFFixed"), (3, "GetThingUDMFInt"),
    (4, "GetThingUDMFFixed"), (5, "GetSectorUDMFInt"), (6, "GetSectorUDMFFixed"),
    (7, "GetSideUDMFInt"), (8, "GetSideUDMFFixed"), (9, "GetActorVelX"),
    (10, "GetActorVelY"), (11, "GetActorVelZ"), (12, "SetActivator"),
    (13, "SetActivatorToTarget"), (14, "GetActorViewHeight"), (15, "GetChar"),
    (16, "GetAirSupply"), (17, "SetAirSupply"), (18, "SetSkyScrollSpeed"),
    (19, "GetArmorType"), (20, "SpawnSpotForced"), (21, "SpawnSpotFacingForced"),
    (22, "CheckActorProperty"), (23, "SetActorVelocity"), (24, "SetUserVariable"),
    (25, "GetUserVariable"), (26, "Radius_Quake2"), (27, "CheckActorClass"),
    (28, "SetUserArray"), (29, "GetUserArray"), (30, "SoundSequenceOnActor"),
    (31, "SoundSequenceOnSector"), (32, "SoundSequenceOnPolyobj"), (33, "GetPolyobjX"),
    (34, "GetPolyobjY"), (35, "CheckSight"), (36, "SpawnForced"), (37, "AnnouncerSound"),
    (38, "SetPointer"), (39, "ACS_NamedExecute"), (40, "ACS_NamedSuspend"),
    (41, "ACS_NamedTerminate"), (42, "ACS_NamedLockedExecute"),
    (43, "ACS_NamedLockedExecuteDoor"), (44, "ACS_NamedExecuteWithResult"),
    (45, "ACS_NamedExecuteAlways"), (46, "UniqueTID"), (47, "IsTIDUsed"), (48, "Sqrt"),
    (49, "FixedSqrt"), (50, "VectorLength"), (51, "SetHUDClipRect"),
    (52, "SetHUDWrapWidth"), (53, "SetCVar"), (54, "GetUserCVar"), (55, "SetUserCVar"),
    (56, "GetCVarString"), (57, "SetCVarString"), (58, "GetUserCVarString"),
    (59, "SetUserCVarString"), (60, "LineAttack"), (61, "PlaySound"), (62, "StopSound"),
    (63, "strcmp"), (64, "stricmp"), (65, "StrLeft"), (66, "StrRight"), (67, "StrMid"),
    (68, "GetActorClass"), (69, "GetWeapon"), (70, "SoundVolume"), (71, "PlayActorSound"),
    (72, "SpawnDecal"), (73, "CheckFont"), (74, "DropItem"), (75, "CheckFlag"),
    (76, "SetLineActivation"), (77, "GetLineActivation"), (78, "GetActorPowerupTics"),
    (79, "ChangeActorAngle"), (80, "ChangeActorPitch"), (81, "GetArmorInfo"),
    (82, "DropInventory"), (83, "PickActor"), (84, "IsPointerEqual"),
    (85, "CanRaiseActor"), (86, "SetActorTeleFog"), (87, "SwapActorTeleFog"),
    (88, "SetActorRoll"), (89, "ChangeActorRoll"), (90, "GetActorRoll"), (91, "QuakeEx"),
    (92, "Warp"), (93, "GetMaxInventory"), (94, "SetSectorDamage"),
    (95, "SetSectorTerrain"), (96, "SpawnParticle"), (97, "SetMusicVolume"),
    (98, "CheckProximity"), (99, "CheckActorState"), (200, "CheckClass"),
    (201, "DamageActor"), (202, "SetActorFlag"), (203, "SetTranslation"),
    (204, "GetActorFloorTexture"), (205, "GetActorFloorTerrain"), (206, "StrArg"),
    (207, "Floor"), (208, "Round"), (209, "Ceil"), (210, "ScriptCall"),
    (211, "StartSlideshow"), (212, "GetSectorHealth"), (213, "GetLineHealth"),
    (214, "SetSubtitleNumber"), (215, "GetNetID"), (216, "SetActivatorByNetID"),
    (300, "GetLineX"), (301, "GetLineY"), (400, "SetSectorGlow"), (401, "SetFogDensity"),
    (19620, "GetTeamScore"), (19621, "SetTeamScore"),
];

/// Name of an extended function (`ACSF_` dropped), if ZDoom defines the id.
pub fn function_name(id: u16) -> Option<&'static str> {
    FUNCTIONS.iter().find(|&&(i, _)| i == id).map(|&(_, n)| n)
}

// The pcodes the VM refers to by name (numbers from acc's `pcode.h`).
pub const NOP: u16 = 0;
pub const TERMINATE: u16 = 1;
pub const SUSPEND: u16 = 2;
pub const PUSHNUMBER: u16 = 3;
pub const LSPEC1: u16 = 4;
pub const LSPEC2: u16 = 5;
pub const LSPEC3: u16 = 6;
pub const LSPEC5: u16 = 8;
pub const LSPEC1DIRECT: u16 = 9;
pub const LSPEC2DIRECT: u16 = 10;
pub const LSPEC5DIRECT: u16 = 13;
pub const ADD: u16 = 14;
pub const SUBTRACT: u16 = 15;
pub const MULTIPLY: u16 = 16;
pub const DIVIDE: u16 = 17;
pub const MODULUS: u16 = 18;
pub const EQ: u16 = 19;
pub const NE: u16 = 20;
pub const LT: u16 = 21;
pub const GT: u16 = 22;
pub const LE: u16 = 23;
pub const GE: u16 = 24;
pub const ASSIGNSCRIPTVAR: u16 = 25;
pub const PUSHSCRIPTVAR: u16 = 28;
pub const GOTO: u16 = 52;
pub const IFGOTO: u16 = 53;
pub const DROP: u16 = 54;
pub const DELAY: u16 = 55;
pub const DELAYDIRECT: u16 = 56;
pub const RANDOM: u16 = 57;
pub const RANDOMDIRECT: u16 = 58;
pub const TAGWAIT: u16 = 61;
pub const TAGWAITDIRECT: u16 = 62;
pub const POLYWAIT: u16 = 63;
pub const POLYWAITDIRECT: u16 = 64;
pub const RESTART: u16 = 69;
pub const ANDLOGICAL: u16 = 70;
pub const ORLOGICAL: u16 = 71;
pub const ANDBITWISE: u16 = 72;
pub const ORBITWISE: u16 = 73;
pub const EORBITWISE: u16 = 74;
pub const NEGATELOGICAL: u16 = 75;
pub const LSHIFT: u16 = 76;
pub const RSHIFT: u16 = 77;
pub const UNARYMINUS: u16 = 78;
pub const IFNOTGOTO: u16 = 79;
pub const SCRIPTWAIT: u16 = 81;
pub const SCRIPTWAITDIRECT: u16 = 82;
pub const CASEGOTO: u16 = 84;
pub const BEGINPRINT: u16 = 85;
pub const ENDPRINT: u16 = 86;
pub const PRINTSTRING: u16 = 87;
pub const PRINTNUMBER: u16 = 88;
pub const PRINTCHARACTER: u16 = 89;
pub const ENDPRINTBOLD: u16 = 101;
pub const FIXEDMUL: u16 = 136;
pub const FIXEDDIV: u16 = 137;
pub const PRINTFIXED: u16 = 157;
pub const PRINTLOCALIZED: u16 = 158;
pub const MOREHUDMESSAGE: u16 = 159;
pub const OPTHUDMESSAGE: u16 = 160;
pub const ENDHUDMESSAGE: u16 = 161;
pub const ENDHUDMESSAGEBOLD: u16 = 162;
pub const PUSHBYTE: u16 = 167;
pub const LSPEC1DIRECTB: u16 = 168;
pub const LSPEC3DIRECTB: u16 = 170;
pub const LSPEC5DIRECTB: u16 = 172;
pub const DELAYDIRECTB: u16 = 173;
pub const RANDOMDIRECTB: u16 = 174;
pub const PUSHBYTES: u16 = 175;
pub const PUSH2BYTES: u16 = 176;
pub const PUSH3BYTES: u16 = 177;
pub const PUSH4BYTES: u16 = 178;
pub const PUSH5BYTES: u16 = 179;
pub const ASSIGNGLOBALVAR: u16 = 181;
pub const PUSHGLOBALVAR: u16 = 182;
pub const INCGLOBALVAR: u16 = 188;
pub const CALL: u16 = 203;
pub const CALLDISCARD: u16 = 204;
pub const RETURNVOID: u16 = 205;
pub const RETURNVAL: u16 = 206;
pub const DUP: u16 = 216;
pub const SWAP: u16 = 217;
pub const SIN: u16 = 220;
pub const COS: u16 = 221;
pub const VECTORANGLE: u16 = 222;
pub const TAGSTRING: u16 = 225;
pub const STRLEN: u16 = 253;
pub const CASEGOTOSORTED: u16 = 256;
pub const SETRESULTVALUE: u16 = 257;
pub const LSPEC5RESULT: u16 = 263;
pub const ENDLOG: u16 = 270;
pub const PRINTMAPCHARARRAY: u16 = 273;
pub const PRINTWORLDCHARARRAY: u16 = 274;
pub const PRINTGLOBALCHARARRAY: u16 = 275;
pub const NEGATEBINARY: u16 = 330;
pub const PRINTBINARY: u16 = 349;
pub const PRINTHEX: u16 = 350;
pub const CALLFUNC: u16 = 351;
pub const SAVESTRING: u16 = 352;
pub const PRINTMAPCHRANGE: u16 = 353;
pub const PRINTWORLDCHRANGE: u16 = 354;
pub const PRINTGLOBALCHRANGE: u16 = 355;
pub const PUSHFUNCTION: u16 = 359;
pub const CALLSTACK: u16 = 360;
pub const SCRIPTWAITNAMED: u16 = 361;
pub const GOTOSTACK: u16 = 363;
pub const PRINTSCRIPTCHARARRAY: u16 = 378;
pub const PRINTSCRIPTCHRANGE: u16 = 379;
pub const LSPEC5EX: u16 = 381;
pub const LSPEC5EXRESULT: u16 = 382;

/// What follows a pcode in the code stream. "Index" operands (variable,
/// function and special numbers) are one byte in the compact ACSe format and
/// four in ACSE (ZDoom's `NEXTBYTE`); "words" are always four bytes, read
/// unaligned; "bytes" are single bytes in either format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Operands {
    None,
    /// One index operand.
    Index,
    /// `n` four-byte words.
    Words(u8),
    /// One four-byte code offset.
    Jump,
    /// A four-byte value and a four-byte code offset.
    CaseGoto,
    /// Padding to a four-byte boundary, a count, then (value, offset) pairs
    /// sorted by value.
    SortedCases,
    /// A special number (index operand) and `n` four-byte arguments.
    SpecialDirect(u8),
    /// `n` single bytes.
    Bytes(u8),
    /// A count byte and that many bytes.
    CountedBytes,
    /// An argument count (index operand) and a function id (two bytes in
    /// ACSe, four in ACSE).
    CallFunc,
}

/// The operands `pcode` carries (ZDoom's `DLevelScript::RunScript`).
pub fn operands(pcode: u16) -> Operands {
    use Operands::*;
    match pcode {
        3 | 56 | 62 | 64 | 82 | 139 | 141 | 148 | 166 | 381 | 382 => Words(1),
        58 | 60 | 66 | 68 | 144 | 146 | 154 | 156 => Words(2),
        152 => Words(4),
        150 => Words(6),
        GOTO | IFGOTO | IFNOTGOTO => Jump,
        CASEGOTO => CaseGoto,
        CASEGOTOSORTED => SortedCases,
        4..=8 | LSPEC5RESULT | CALL | CALLDISCARD | PUSHFUNCTION => Index,
        LSPEC1DIRECT..=LSPEC5DIRECT => SpecialDirect((pcode - LSPEC1DIRECT + 1) as u8),
        PUSHBYTE | DELAYDIRECTB => Bytes(1),
        LSPEC1DIRECTB..=LSPEC5DIRECTB => Bytes((pcode - LSPEC1DIRECTB + 2) as u8),
        RANDOMDIRECTB => Bytes(2),
        PUSH2BYTES..=PUSH5BYTES => Bytes((pcode - PUSH2BYTES + 2) as u8),
        PUSHBYTES => CountedBytes,
        CALLFUNC => CallFunc,
        _ if var_op(pcode).is_some() => Index,
        _ => None,
    }
}

/// The arithmetic a variable pcode applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VarOp {
    Assign,
    Push,
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Inc,
    Dec,
    And,
    Eor,
    Or,
    Shl,
    Shr,
}

/// Where a variable pcode's variable lives; the index operand selects it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Store {
    ScriptVar,
    MapVar,
    WorldVar,
    GlobalVar,
    ScriptArray,
    MapArray,
    WorldArray,
    GlobalArray,
}

const STORES: [Store; 8] = [
    Store::ScriptVar,
    Store::MapVar,
    Store::WorldVar,
    Store::GlobalVar,
    Store::ScriptArray,
    Store::MapArray,
    Store::WorldArray,
    Store::GlobalArray,
];

/// The variable pcodes, one row per operation, columns in `STORES` order.
/// The numbers are scattered because each storage class was added to the
/// language at a different time (Hexen, ZDoom 1.23, 2.0, ...).
const VAR_OPS: [(VarOp, [u16; 8]); 14] = [
    (VarOp::Assign, [25, 26, 27, 181, 364, 208, 227, 236]),
    (VarOp::Push, [28, 29, 30, 182, 365, 207, 226, 235]),
    (VarOp::Add, [31, 32, 33, 183, 366, 209, 228, 237]),
    (VarOp::Sub, [34, 35, 36, 184, 367, 210, 229, 238]),
    (VarOp::Mul, [37, 38, 39, 185, 368, 211, 230, 239]),
    (VarOp::Div, [40, 41, 42, 186, 369, 212, 231, 240]),
    (VarOp::Mod, [43, 44, 45, 187, 370, 213, 232, 241]),
    (VarOp::Inc, [46, 47, 48, 188, 371, 214, 233, 242]),
    (VarOp::Dec, [49, 50, 51, 189, 372, 215, 234, 243]),
    (VarOp::And, [291, 292, 293, 294, 373, 295, 296, 297]),
    (VarOp::Eor, [298, 299, 300, 301, 374, 302, 303, 304]),
    (VarOp::Or, [305, 306, 307, 308, 375, 309, 310, 311]),
    (VarOp::Shl, [312, 313, 314, 315, 376, 316, 317, 318]),
    (VarOp::Shr, [319, 320, 321, 322, 377, 323, 324, 325]),
];

/// The operation and storage of a variable pcode.
pub fn var_op(pcode: u16) -> Option<(VarOp, Store)> {
    VAR_OPS.iter().find_map(|(op, row)| row.iter().position(|&p| p == pcode).map(|i| (*op, STORES[i])))
}

/// A pcode the VM hands to the game ([`super::Host::game`]): how many values
/// it takes and whether it leaves one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GameOp {
    /// The stack form; a `...DIRECT` pcode is reported as its stack form,
    /// its immediate operands as the arguments (zero-padded to `args`).
    pub pcode: u16,
    pub args: u8,
    pub pushes: bool,
}

/// Stack forms of the game pcodes: (pcode, arguments popped, pushes a value).
/// Counts from the `sp -=` of each case in ZDoom's `RunScript`.
const GAME_OPS: &[(u16, u8, bool)] = &[
    (59, 2, true),   // THINGCOUNT
    (65, 2, false),  // CHANGEFLOOR
    (67, 2, false),  // CHANGECEILING
    (80, 0, true),   // LINESIDE
    (83, 0, false),  // CLEARLINESPECIAL
    (90, 0, true),   // PLAYERCOUNT
    (91, 0, true),   // GAMETYPE
    (92, 0, true),   // GAMESKILL
    (93, 0, true),   // TIMER
    (94, 2, false),  // SECTORSOUND
    (95, 2, false),  // AMBIENTSOUND
    (96, 1, false),  // SOUNDSEQUENCE
    (97, 4, false),  // SETLINETEXTURE
    (98, 2, false),  // SETLINEBLOCKING
    (99, 7, false),  // SETLINESPECIAL
    (100, 3, false), // THINGSOUND
    (102, 2, false), // ACTIVATORSOUND
    (103, 2, false), // LOCALAMBIENTSOUND
    (104, 2, false), // SETLINEMONSTERBLOCKING
    (135, 0, true),  // SINGLEPLAYER
    (138, 1, false), // SETGRAVITY
    (140, 1, false), // SETAIRCONTROL
    (142, 0, false), // CLEARINVENTORY
    (143, 2, false), // GIVEINVENTORY
    (145, 2, false), // TAKEINVENTORY
    (147, 1, true),  // CHECKINVENTORY
    (149, 6, true),  // SPAWN
    (151, 4, true),  // SPAWNSPOT
    (153, 3, false), // SETMUSIC
    (155, 3, false), // LOCALSETMUSIC
    (165, 1, false), // SETFONT
    (180, 7, false), // SETTHINGSPECIAL
    (190, 5, false), // FADETO
    (191, 9, false), // FADERANGE
    (192, 0, false), // CANCELFADE
    (196, 1, true),  // GETACTORX
    (197, 1, true),  // GETACTORY
    (198, 1, true),  // GETACTORZ
    (223, 1, true),  // CHECKWEAPON
    (224, 1, true),  // SETWEAPON
    (245, 3, false), // SETACTORPROPERTY
    (246, 2, true),  // GETACTORPROPERTY
    (247, 0, true),  // PLAYERNUMBER
    (248, 0, true),  // ACTIVATORTID
    (250, 0, true),  // GETSCREENWIDTH
    (251, 0, true),  // GETSCREENHEIGHT
    (252, 7, false), // THING_PROJECTILE2
    (254, 3, false), // SETHUDSIZE
    (255, 1, true),  // GETCVAR
    (258, 0, true),  // GETLINEROWOFFSET
    (259, 1, true),  // GETACTORFLOORZ
    (260, 1, true),  // GETACTORANGLE
    (261, 3, true),  // GETSECTORFLOORZ
    (262, 3, true),  // GETSECTORCEILINGZ
    (265, 1, true),  // GETLEVELINFO
    (266, 2, false), // CHANGESKY
    (267, 1, true),  // PLAYERINGAME
    (268, 1, true),  // PLAYERISBOT
    (269, 3, false), // SETCAMERATOTEXTURE
    (271, 1, true),  // GETAMMOCAPACITY
    (272, 2, false), // SETAMMOCAPACITY
    (276, 2, false), // SETACTORANGLE
    (280, 7, false), // SPAWNPROJECTILE
    (281, 1, true),  // GETSECTORLIGHTLEVEL
    (282, 1, true),  // GETACTORCEILINGZ
    (283, 5, true),  // SETACTORPOSITION
    (284, 1, false), // CLEARACTORINVENTORY
    (285, 3, false), // GIVEACTORINVENTORY
    (286, 3, false), // TAKEACTORINVENTORY
    (287, 2, true),  // CHECKACTORINVENTORY
    (288, 2, true),  // THINGCOUNTNAME
    (289, 3, true),  // SPAWNSPOTFACING
    (290, 1, true),  // PLAYERCLASS
    (326, 2, true),  // GETPLAYERINFO
    (327, 4, false), // CHANGELEVEL
    (328, 5, false), // SECTORDAMAGE
    (329, 3, false), // REPLACETEXTURES
    (331, 1, true),  // GETACTORPITCH
    (332, 2, false), // SETACTORPITCH
    (334, 3, true),  // SETACTORSTATE
    (335, 3, true),  // THINGDAMAGE2
    (336, 1, true),  // USEINVENTORY
    (337, 2, true),  // USEACTORINVENTORY
    (338, 2, true),  // CHECKACTORCEILINGTEXTURE
    (339, 2, true),  // CHECKACTORFLOORTEXTURE
    (340, 1, true),  // GETACTORLIGHTLEVEL
    (341, 1, false), // SETMUGSHOTSTATE
    (342, 3, true),  // THINGCOUNTSECTOR
    (343, 3, true),  // THINGCOUNTNAMESECTOR
    (344, 1, true),  // CHECKPLAYERCAMERA
    (345, 7, true),  // MORPHACTOR
    (346, 2, true),  // UNMORPHACTOR
    (347, 2, true),  // GETPLAYERINPUT
    (348, 1, true),  // CLASSIFYACTOR
];

/// The `...DIRECT` forms of game pcodes: (direct pcode, its stack form).
const GAME_DIRECT: &[(u16, u16)] = &[
    (60, 59),   // THINGCOUNTDIRECT
    (66, 65),   // CHANGEFLOORDIRECT
    (68, 67),   // CHANGECEILINGDIRECT
    (139, 138), // SETGRAVITYDIRECT
    (141, 140), // SETAIRCONTROLDIRECT
    (144, 143), // GIVEINVENTORYDIRECT
    (146, 145), // TAKEINVENTORYDIRECT
    (148, 147), // CHECKINVENTORYDIRECT
    (150, 149), // SPAWNDIRECT
    (152, 151), // SPAWNSPOTDIRECT
    (154, 153), // SETMUSICDIRECT
    (156, 155), // LOCALSETMUSICDIRECT
    (166, 165), // SETFONTDIRECT
];

/// The game pcode `pcode` is, with a flag for the direct form.
pub fn game_op(pcode: u16) -> Option<(GameOp, bool)> {
    let (stack, direct) = match GAME_DIRECT.iter().find(|&&(d, _)| d == pcode) {
        Some(&(_, s)) => (s, true),
        None => (pcode, false),
    };
    GAME_OPS
        .iter()
        .find(|&&(p, _, _)| p == stack)
        .map(|&(pcode, args, pushes)| (GameOp { pcode, args, pushes }, direct))
}

/// Whether the VM executes `pcode`. Everything else is refused when a
/// module loads, with the pcode's name and offset.
pub fn supported(pcode: u16) -> bool {
    matches!(
        pcode,
        NOP..=LSPEC5DIRECT
            | ADD..=GE
            | GOTO..=RANDOMDIRECT
            | TAGWAIT..=POLYWAITDIRECT
            | RESTART..=IFNOTGOTO
            | SCRIPTWAIT..=PRINTCHARACTER
            | ENDPRINTBOLD
            | FIXEDMUL
            | FIXEDDIV
            | PRINTFIXED..=ENDHUDMESSAGEBOLD
            | PUSHBYTE..=PUSH5BYTES
            | CALL..=RETURNVAL
            | DUP
            | SWAP
            | SIN..=VECTORANGLE
            | TAGSTRING
            | STRLEN
            | CASEGOTOSORTED..=LSPEC5RESULT
            | ENDLOG..=PRINTGLOBALCHARARRAY
            | NEGATEBINARY
            | PRINTBINARY..=PRINTGLOBALCHRANGE
            | PUSHFUNCTION..=SCRIPTWAITNAMED
            | GOTOSTACK
            | PRINTSCRIPTCHARARRAY
            | PRINTSCRIPTCHRANGE
            | LSPEC5EX
            | LSPEC5EXRESULT
    ) || var_op(pcode).is_some()
        || game_op(pcode).is_some()
}
