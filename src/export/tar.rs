//! A deterministic ustar writer and reader: every header field that could vary (time, owner,
//! permissions) is fixed, so the same members give the same archive bytes on every node.

use std::io::{self, Write};

const BLOCK: usize = 512;

/// Writes one regular-file member: a 512-byte header, the data, zero padding to 512 bytes.
///
/// # Errors
/// When the name is longer than 100 bytes or the writer fails.
pub fn write_member(out: &mut impl Write, name: &str, data: &[u8]) -> io::Result<()> {
    if name.len() > 100 || name.is_empty() {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("tar member name {name:?} must be 1..=100 bytes"),
        ));
    }
    let mut h = [0u8; BLOCK];
    h[..name.len()].copy_from_slice(name.as_bytes());
    octal(&mut h[100..108], 0o644);
    octal(&mut h[108..116], 0);
    octal(&mut h[116..124], 0);
    octal(&mut h[124..136], data.len() as u64);
    octal(&mut h[136..148], 0);
    h[148..156].fill(b' ');
    h[156] = b'0';
    h[257..263].copy_from_slice(b"ustar\0");
    h[263..265].copy_from_slice(b"00");
    let sum: u32 = h.iter().map(|b| *b as u32).sum();
    let field = format!("{sum:06o}\0 ");
    h[148..156].copy_from_slice(field.as_bytes());
    out.write_all(&h)?;
    out.write_all(data)?;
    let pad = (BLOCK - data.len() % BLOCK) % BLOCK;
    out.write_all(&[0u8; BLOCK][..pad])
}

/// Writes the end-of-archive marker (two zero blocks).
pub fn finish(out: &mut impl Write) -> io::Result<()> {
    out.write_all(&[0u8; 2 * BLOCK])
}

fn octal(field: &mut [u8], value: u64) {
    let digits = field.len() - 1;
    let s = format!("{value:0digits$o}");
    field[..digits].copy_from_slice(s.as_bytes());
    field[digits] = 0;
}

/// Reads the members of an archive written by this module: `(name, data)` in order.
///
/// # Errors
/// On a truncated or malformed archive.
pub fn read_members(mut bytes: &[u8]) -> io::Result<Vec<(String, Vec<u8>)>> {
    let bad = |m: &str| io::Error::new(io::ErrorKind::InvalidData, m.to_string());
    let mut out = Vec::new();
    while bytes.len() >= BLOCK {
        let h = &bytes[..BLOCK];
        if h.iter().all(|b| *b == 0) {
            break;
        }
        let name_len = h[..100].iter().position(|b| *b == 0).unwrap_or(100);
        let name = String::from_utf8(h[..name_len].to_vec())
            .map_err(|_| bad("member name is not UTF-8"))?;
        let size_text = std::str::from_utf8(&h[124..135]).map_err(|_| bad("size field"))?;
        let size = u64::from_str_radix(size_text.trim_matches(|c| c == '\0' || c == ' '), 8)
            .map_err(|_| bad("size field"))? as usize;
        let padded = size.div_ceil(BLOCK) * BLOCK;
        if bytes.len() < BLOCK + padded {
            return Err(bad("truncated member"));
        }
        out.push((name, bytes[BLOCK..BLOCK + size].to_vec()));
        bytes = &bytes[BLOCK + padded..];
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn members_round_trip_and_headers_are_deterministic() {
        let mut a = Vec::new();
        write_member(&mut a, "tiles/0/-1/2.bin", b"hello").expect("write");
        write_member(&mut a, "empty", b"").expect("write");
        finish(&mut a).expect("finish");
        assert_eq!(a.len() % 512, 0);
        let members = read_members(&a).expect("read");
        assert_eq!(
            members,
            vec![
                ("tiles/0/-1/2.bin".to_string(), b"hello".to_vec()),
                ("empty".to_string(), vec![])
            ]
        );
        let mut b = Vec::new();
        write_member(&mut b, "tiles/0/-1/2.bin", b"hello").expect("write");
        write_member(&mut b, "empty", b"").expect("write");
        finish(&mut b).expect("finish");
        assert_eq!(a, b);
        assert!(write_member(&mut Vec::new(), &"x".repeat(101), b"").is_err());
    }

    #[test]
    fn system_tar_reads_the_archive() {
        let dir = std::env::temp_dir().join(format!("strata-tar-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("dir");
        let mut a = Vec::new();
        write_member(&mut a, "a/b.txt", b"strata").expect("write");
        finish(&mut a).expect("finish");
        let path = dir.join("t.tar");
        std::fs::write(&path, &a).expect("write tar");
        let out = std::process::Command::new("tar")
            .arg("-tvf")
            .arg(&path)
            .output()
            .expect("run tar");
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(String::from_utf8_lossy(&out.stdout).contains("a/b.txt"));
    }
}
