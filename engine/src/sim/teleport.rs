//! Teleporters (`p_telept.c`): `EV_Teleport`.
